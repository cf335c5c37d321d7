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
  for (auto& b : more) std::fill(b.begin(), b.end(), glm::vec4(0.0f));
}

void Framebuffer::reset(int w, int h, glm::vec4 clear_color, const Parallel& parallel, bool with_aux) {
  w = w > 0 ? w : 0;
  h = h > 0 ? h : 0;
  const std::size_t n = std::size_t(w) * std::size_t(h);
  if (w != width || h != height || color.size() != n || depth.size() != n) {
    // Each target written once, with its clear value; a dropped draw buffer 1 is not built at all
    // (a one-shot render paid 16 MiB of page faults for it at 1024x1024).
    const int buffers = draw_buffers();
    width = w;
    height = h;
    color.assign(n, clear_color);
    depth.assign(n, 1.0f);
    if (with_aux) aux.assign(n, glm::vec4(0.0f));
    else aux = {};
    for (int k = 2; k < kMaxDrawBuffers; ++k) {
      std::vector<glm::vec4>& m = more[std::size_t(k - 2)];
      if (k < buffers) m.assign(n, glm::vec4(0.0f));
      else m = {};
    }
    return;
  }
  if (!with_aux) aux.clear();               // capacity kept
  else if (aux.size() != n) aux.resize(n);  // cleared below
  constexpr std::size_t kPixelsPerTask = 1 << 16;
  parallel.for_each((n + kPixelsPerTask - 1) / kPixelsPerTask, [&](std::size_t t) {
    const std::size_t a = t * kPixelsPerTask, b = std::min(n, a + kPixelsPerTask);
    std::fill(color.begin() + a, color.begin() + b, clear_color);
    std::fill(depth.begin() + a, depth.begin() + b, 1.0f);
    if (!aux.empty()) std::fill(aux.begin() + a, aux.begin() + b, glm::vec4(0.0f));
    for (auto& m : more)
      if (!m.empty()) std::fill(m.begin() + a, m.begin() + b, glm::vec4(0.0f));
  });
}

void Framebuffer::set_draw_buffers(int n) {
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  if (n >= 2 && aux.size() != pixels) aux.assign(pixels, glm::vec4(0.0f));
  if (n < 2) aux.clear();
  for (int k = 2; k < kMaxDrawBuffers; ++k) {
    std::vector<glm::vec4>& b = more[std::size_t(k - 2)];
    if (k < n) {
      if (b.size() != pixels) b.assign(pixels, glm::vec4(0.0f));
    } else {
      b.clear();
    }
  }
}

std::vector<glm::vec4>* Framebuffer::draw_buffer(int k) {
  return const_cast<std::vector<glm::vec4>*>(static_cast<const Framebuffer*>(this)->draw_buffer(k));
}

const std::vector<glm::vec4>* Framebuffer::draw_buffer(int k) const {
  const std::vector<glm::vec4>* b = k == 0 ? &color : k == 1 ? &aux : k < kMaxDrawBuffers ? &more[std::size_t(k - 2)] : nullptr;
  return b && !b->empty() ? b : nullptr;
}

int Framebuffer::draw_buffers() const {
  for (int k = kMaxDrawBuffers - 1; k >= 0; --k)
    if (draw_buffer(k)) return k + 1;
  return 0;
}

}  // namespace tessref
