#pragma once
// Color, depth and one auxiliary attachment (normals for the EXR dump), GL window convention:
// row 0 is the bottom row, pixel (x, y) has its center at (x + 0.5, y + 0.5).
#include <vector>

#include <glm/glm.hpp>

#include "common/parallel.h"

namespace tessref {

struct Framebuffer {
  int width = 0;
  int height = 0;
  std::vector<glm::vec4> color;  // linear RGBA as written by the fragment shader
  std::vector<float> depth;      // window-space depth in [0, 1]; cleared to 1
  std::vector<glm::vec4> aux;    // second fragment output (e.g. world normal), cleared to 0

  Framebuffer() = default;
  Framebuffer(int w, int h, glm::vec4 clear_color = glm::vec4(0.0f));
  void clear(glm::vec4 clear_color);
  // Makes the framebuffer w x h and clears it, reusing its memory when the size is unchanged (a
  // frame drawn again then pays no allocation and no page faults), on all of parallel's threads.
  void reset(int w, int h, glm::vec4 clear_color, const Parallel& parallel);
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width + x; }
};

}  // namespace tessref
