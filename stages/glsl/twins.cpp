#include "stages/glsl/twins.h"

#include <stdexcept>

namespace tessref::glsl {

std::string twin_source(const std::string& name) {
  for (const Twin* t = kTwins; t->name; ++t)
    if (name == t->name) return t->source;
  throw std::invalid_argument("no built-in GLSL twin named '" + name + "'");
}

}  // namespace tessref::glsl
