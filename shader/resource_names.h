#pragma once
// The accessors of a GL resource name (OpenGL 4.5, 7.3.1.1): after a variable's (or a block
// member's) own name, "[i]" selects an array element and ".member" a structure member, as
// glGetUniformLocation and glTransformFeedbackVaryings take them ("lights[2].color").
#include <cstdint>
#include <string>
#include <string_view>

#include "shader/spirv_module.h"

namespace tessref::shader {

// A value inside a variable: its type and first word.
struct NamedValue {
  std::uint32_t type = 0, word = 0;
  std::uint32_t remaining = 1;  // elements from this one to the end of its array (1: not an element)
};

struct Access {
  NamedValue value;
  // Empty when every accessor applied; else why not, naming what was reached ("weights is not an
  // array", "s has no member 'n'", "weights has 4 elements"), or that the text is no accessor.
  std::string why;
  bool malformed = false;       // why: the text is not a sequence of accessors
  bool index_past_end = false;  // why: an index past its array's `count` elements, written `index`
  std::string index;
  std::uint32_t count = 0;
};

// Follows `accessors` (the name's text after `head`, the part already resolved to `at`).
Access follow_accessors(const Module& m, NamedValue at, std::string_view head, std::string_view accessors);

}  // namespace tessref::shader
