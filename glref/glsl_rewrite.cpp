#include "glref/glsl_rewrite.h"

#include <regex>

#include "glref/gl_error.h"
#include "glref/shader_source.h"

namespace tessref::glref {
namespace {

// The first whole line of `source` matching `pattern`: its start (npos if none) and length
// without the newline; `groups` gets the match.
std::size_t find_line(const std::string& source, const std::regex& pattern, std::size_t& length,
                      std::string& text, std::smatch& groups) {
  std::size_t pos = 0;
  while (pos < source.size()) {
    const std::size_t eol = source.find('\n', pos);
    length = (eol == std::string::npos ? source.size() : eol) - pos;
    text = source.substr(pos, length);
    if (std::regex_match(text, groups, pattern)) return pos;
    if (eol == std::string::npos) break;
    pos = eol + 1;
  }
  return std::string::npos;
}

// Replaces the first whole line matching `line`, newline included, with `replacement` (which ends
// in a newline).
bool replace_line(std::string& source, const std::regex& line, const std::string& replacement) {
  std::size_t length = 0;
  std::string text;
  std::smatch groups;
  const std::size_t pos = find_line(source, line, length, text, groups);
  if (pos == std::string::npos) return false;
  source.replace(pos, pos + length < source.size() ? length + 1 : length, replacement);
  return true;
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

std::string specialize_uniforms(const std::string& source, const std::vector<UniformConstant>& constants) {
  std::string out = source;
  for (const UniformConstant& c : constants) {
    // One declaration per line in the twins: "uniform int u_num_lights;  // comment".
    const std::regex decl(R"(\s*uniform\s+(int|uint|bool|float)\s+)" + c.name + R"(\s*;(.*))");
    std::size_t length = 0;
    std::string text;
    std::smatch m;
    const std::size_t pos = find_line(out, decl, length, text, m);
    if (pos != std::string::npos)
      out.replace(pos, length, "const " + m[1].str() + " " + c.name + " = " + c.value + ";" + m[2].str());
  }
  return out;
}

}  // namespace tessref::glref
