#include "glref/glsl_rewrite.h"

#include <regex>

#include "glref/gl_error.h"
#include "glref/shader_source.h"

namespace tessref::glref {
namespace {

// Replaces the first whole line matching `line` with `replacement` (which ends in a newline).
bool replace_line(std::string& source, const std::regex& line, const std::string& replacement) {
  std::size_t pos = 0;
  while (pos < source.size()) {
    std::size_t eol = source.find('\n', pos);
    const std::size_t len = (eol == std::string::npos ? source.size() : eol) - pos;
    if (std::regex_match(source.substr(pos, len), line)) {
      source.replace(pos, eol == std::string::npos ? len : len + 1, replacement);
      return true;
    }
    if (eol == std::string::npos) break;
    pos = eol + 1;
  }
  return false;
}

}  // namespace

std::string tes_layout_qualifier(const TessLayout& layout) {
  std::string s = std::string("layout(") + glsl_name(layout.domain) + ", " + glsl_name(layout.spacing) +
                  ", " + glsl_name(layout.winding);
  if (layout.point_mode) s += ", point_mode";
  return s + ") in;\n";
}

std::string set_tes_layout(const std::string& source, const TessLayout& layout) {
  static const std::regex tes_line(R"(\s*layout\s*\([^)]*\b(triangles|quads|isolines)\b[^)]*\)\s*in\s*;.*)");
  std::string out = source;
  if (!replace_line(out, tes_line, tes_layout_qualifier(layout)))
    throw GlError("no TES input layout line (layout(triangles|quads|isolines, ...) in;) to rewrite");
  if (layout.domain == TessDomain::Quads) out = inject_after_version(out, "#define TESSREF_QUADS\n");
  if (layout.domain == TessDomain::Isolines) out = inject_after_version(out, "#define TESSREF_ISOLINES\n");
  return out;
}

std::string set_tcs_vertices(const std::string& source, int vertices) {
  static const std::regex tcs_line(R"(\s*layout\s*\(\s*vertices\s*=\s*\d+\s*\)\s*out\s*;.*)");
  std::string out = source;
  if (!replace_line(out, tcs_line, "layout(vertices = " + std::to_string(vertices) + ") out;\n"))
    throw GlError("no TCS output layout line (layout(vertices = N) out;) to rewrite");
  return out;
}

}  // namespace tessref::glref
