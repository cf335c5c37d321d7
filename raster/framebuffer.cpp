#include "raster/framebuffer.h"

#include <algorithm>

namespace tessref {

Framebuffer::Framebuffer(int w, int h, glm::vec4 clear_color)
    : width(w > 0 ? w : 0), height(h > 0 ? h : 0) {
  // Constructed with their clear values: one pass over the memory, not a zero fill and a clear.
  const std::size_t n = std::size_t(width) * std::size_t(height);
  color.assign(n, clear_color);
  depth.assign(n, 1.0f);
  aux.assign(n, glm::vec4(0.0f));
}

void Framebuffer::clear(glm::vec4 clear_color) {
  std::fill(color.begin(), color.end(), clear_color);
  std::fill(depth.begin(), depth.end(), 1.0f);
  std::fill(aux.begin(), aux.end(), glm::vec4(0.0f));
}

void Framebuffer::reset(int w, int h, glm::vec4 clear_color, const Parallel& parallel) {
  w = w > 0 ? w : 0;
  h = h > 0 ? h : 0;
  const std::size_t n = std::size_t(w) * std::size_t(h);
  if (w != width || h != height || color.size() != n || depth.size() != n || aux.size() != n) {
    *this = Framebuffer(w, h, clear_color);
    return;
  }
  constexpr std::size_t kPixelsPerTask = 1 << 16;
  parallel.for_each((n + kPixelsPerTask - 1) / kPixelsPerTask, [&](std::size_t t) {
    const std::size_t a = t * kPixelsPerTask, b = std::min(n, a + kPixelsPerTask);
    std::fill(color.begin() + a, color.begin() + b, clear_color);
    std::fill(depth.begin() + a, depth.begin() + b, 1.0f);
    std::fill(aux.begin() + a, aux.begin() + b, glm::vec4(0.0f));
  });
}

}  // namespace tessref
