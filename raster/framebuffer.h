#pragma once
// The framebuffer: colour attachments (draw buffers 0 to 7), depth, GL window convention: row 0
// is the bottom row, pixel (x, y) has its center at (x + 0.5, y + 0.5).
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "common/parallel.h"
#include "raster/color_format.h"

namespace tessref {

// GL_MAX_DRAW_BUFFERS as llvmpipe reports it: fragment outputs at locations 0 to 7.
inline constexpr int kMaxDrawBuffers = 8;
// The side of the square tiles the rasterizer scans one at a time (raster/draw.cpp), in pixels;
// a deferred clear (Framebuffer::reset) is kept per tile of this size.
inline constexpr int kFramebufferTileSize = 64;

struct Framebuffer {
  int width = 0;
  int height = 0;
  std::vector<glm::vec4> color;  // draw buffer 0: what the fragment shader writes at location 0
  std::vector<float> depth;      // window-space depth in [0, 1]; cleared to 1
  std::vector<glm::vec4> aux;    // draw buffer 1 (location 1; the mesh path's world normal), cleared to 0
  // Draw buffers 2 to 7, each empty unless the scene's framebuffer has it (set_draw_buffers).
  std::array<std::vector<glm::vec4>, kMaxDrawBuffers - 2> more;
  // Each draw buffer's internal format and the depth buffer's (GL_RGBA32F and
  // GL_DEPTH_COMPONENT32F unless the scene says otherwise): the values kept are those the format
  // holds (raster/color_format.h).
  std::array<ColorFormat, kMaxDrawBuffers> color_format{};
  DepthFormat depth_format = DepthFormat::k32F;

  Framebuffer() = default;
  Framebuffer(int w, int h, glm::vec4 clear_color = glm::vec4(0.0f));
  void clear(glm::vec4 clear_color);
  // Makes the framebuffer w x h and clears it, reusing its memory when the size is unchanged (a
  // frame drawn again then pays no allocation and no page faults), on all of parallel's threads.
  // Draw buffers 2 to 7 and the formats are kept. with_aux false: draw buffer 1 is dropped (its
  // memory kept for a later frame that has it), so it is neither cleared nor written.
  // defer_clear, when the size is unchanged: nothing is written yet; every tile is marked pending,
  // the draws' tile scans clear a tile just before they first touch it (so its pixels are in
  // cache when the depth test reads them), and finish_clear clears the tiles no draw touched.
  // Only for a sequence of draw_triangles / draw_lines / draw_points calls ended by finish_clear:
  // nothing else may read or write the framebuffer in between.
  void reset(int w, int h, glm::vec4 clear_color, const Parallel& parallel, bool with_aux = true,
             bool defer_clear = false);
  // Deferred clear: one tile (its pixels, every target; nothing unless it is pending), and the
  // pending ones that are left.
  bool clear_pending() const { return !pending_tiles_.empty(); }
  void clear_tile(int tile_x, int tile_y);
  void finish_clear(const Parallel& parallel);
  // Gives the framebuffer draw buffers 0 .. n - 1 (n in 1..8; buffers from 2 on cleared to 0, the
  // others dropped).
  void set_draw_buffers(int n);
  // Draw buffer k, or null when there is none (aux and more[] may be empty).
  std::vector<glm::vec4>* draw_buffer(int k);
  const std::vector<glm::vec4>* draw_buffer(int k) const;
  int draw_buffers() const;  // 1 + the highest draw buffer present
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width + x; }
  int tiles_x() const { return (width + kFramebufferTileSize - 1) / kFramebufferTileSize; }
  int tiles_y() const { return (height + kFramebufferTileSize - 1) / kFramebufferTileSize; }

 private:
  // Pixels a .. b - 1 (indices) of every target to their clear values.
  void clear_pixels(std::size_t a, std::size_t b, glm::vec4 clear_color);
  std::vector<std::uint8_t> pending_tiles_;  // per tile, row by row: 1 while its clear is pending
  glm::vec4 pending_color_{0.0f};
};

}  // namespace tessref
