#pragma once
// The built-in programs' GLSL twins (stages/programs/*.vert, *.frag, stages/schemes/*.tesc, *.tese),
// embedded at configure time.
#include <string>

namespace tessref::glsl {

struct Twin {
  const char* name;    // file name, e.g. "pn_triangles.tese"
  const char* source;  // its text
};
extern const Twin kTwins[];  // ends with {nullptr, nullptr}

// The text of the twin with this file name; throws std::invalid_argument if there is none.
std::string twin_source(const std::string& name);

}  // namespace tessref::glsl
