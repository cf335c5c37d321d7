#pragma once
// GLSL sources for the runner, kept as files under glref/shaders/ and embedded at configure time.
#include <string>

namespace tessref::glref {

struct EmbeddedShader {
  const char* name;    // file name under glref/shaders/
  const char* source;  // its text
};
extern const EmbeddedShader kEmbeddedShaders[];  // ends with {nullptr, nullptr}

// The text of glref/shaders/<name>. If TESSREF_GLREF_SHADER_DIR is set, reads <dir>/<name> from
// disk instead (edit shaders without reconfiguring). Throws GlError if not found.
std::string shader_source(const std::string& name);

// Inserts `text` (whole lines) right after the #version line, where layout qualifiers and
// #defines must go. Throws GlError if the source has no #version line.
std::string inject_after_version(const std::string& source, const std::string& text);

}  // namespace tessref::glref
