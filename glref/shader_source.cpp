#include "glref/shader_source.h"

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "glref/gl_error.h"
#include "stages/glsl/twins.h"

namespace tessref::glref {

std::string shader_source(const std::string& name) {
  if (const char* dir = std::getenv("TESSREF_GLREF_SHADER_DIR"); dir && *dir) {
    std::string path = std::string(dir) + "/" + name;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw GlError("cannot read shader " + path + " (TESSREF_GLREF_SHADER_DIR)");
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }
  for (const EmbeddedShader* s = kEmbeddedShaders; s->name; ++s)
    if (name == s->name) return s->source;
  for (const glsl::Twin* t = glsl::kTwins; t->name; ++t)  // the built-in programs' twins
    if (name == t->name) return t->source;
  throw GlError("no embedded shader named " + name + " (glref/shaders/; re-run cmake after adding one)");
}

std::string inject_after_version(const std::string& source, const std::string& text) {
  std::size_t pos = 0;
  while (pos < source.size()) {
    std::size_t eol = source.find('\n', pos);
    if (eol == std::string::npos) eol = source.size();
    std::size_t first = source.find_first_not_of(" \t", pos);
    if (first < eol && source.compare(first, 8, "#version") == 0) {
      std::string out = source.substr(0, eol);
      out += '\n';
      out += text;
      if (!text.empty() && text.back() != '\n') out += '\n';
      if (eol < source.size()) out += source.substr(eol + 1);
      return out;
    }
    pos = eol + 1;
  }
  throw GlError("shader source has no #version line");
}

}  // namespace tessref::glref
