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
  pending_tiles_.clear();
  std::fill(color.begin(), color.end(), clear_color);
  std::fill(depth.begin(), depth.end(), 1.0f);
  std::fill(aux.begin(), aux.end(), glm::vec4(0.0f));
  for (auto& b : more) std::fill(b.begin(), b.end(), glm::vec4(0.0f));
}

void Framebuffer::reset(int w, int h, glm::vec4 clear_color, const Parallel& parallel, bool with_aux,
                        bool defer_clear) {
  w = w > 0 ? w : 0;
  h = h > 0 ? h : 0;
  const std::size_t n = std::size_t(w) * std::size_t(h);
  pending_tiles_.clear();
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
  if (defer_clear && n > 0) {
    pending_tiles_.assign(std::size_t(tiles_x()) * std::size_t(tiles_y()), 1);
    pending_color_ = clear_color;
    return;
  }
  constexpr std::size_t kPixelsPerTask = 1 << 16;
  parallel.for_each((n + kPixelsPerTask - 1) / kPixelsPerTask, [&](std::size_t t) {
    const std::size_t a = t * kPixelsPerTask;
    clear_pixels(a, std::min(n, a + kPixelsPerTask), clear_color);
  });
}

void Framebuffer::clear_pixels(std::size_t a, std::size_t b, glm::vec4 clear_color) {
  std::fill(color.begin() + a, color.begin() + b, clear_color);
  std::fill(depth.begin() + a, depth.begin() + b, 1.0f);
  if (!aux.empty()) std::fill(aux.begin() + a, aux.begin() + b, glm::vec4(0.0f));
  for (auto& m : more)
    if (!m.empty()) std::fill(m.begin() + a, m.begin() + b, glm::vec4(0.0f));
}

void Framebuffer::clear_tile(int tile_x, int tile_y) {
  const std::size_t tile = std::size_t(tile_y) * tiles_x() + tile_x;
  if (tile >= pending_tiles_.size() || !pending_tiles_[tile]) return;
  pending_tiles_[tile] = 0;  // one byte per tile: tiles scanned on different threads never share one
  const int x0 = tile_x * kFramebufferTileSize, x1 = std::min(width, x0 + kFramebufferTileSize);
  const int y0 = tile_y * kFramebufferTileSize, y1 = std::min(height, y0 + kFramebufferTileSize);
  for (int y = y0; y < y1; ++y) clear_pixels(index(x0, y), index(x1 - 1, y) + 1, pending_color_);
}

void Framebuffer::finish_clear(const Parallel& parallel) {
  if (pending_tiles_.empty()) return;
  const int tx = tiles_x();
  parallel.for_each(pending_tiles_.size(), [&](std::size_t t) { clear_tile(int(t % tx), int(t / tx)); });
  pending_tiles_.clear();
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
