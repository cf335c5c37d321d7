#include "raster/clear.h"

#include <algorithm>


namespace tessref {

void clear_buffers(Framebuffer& fb, const RasterState& state, const std::optional<glm::vec4>& color,
                   const std::optional<float>& depth) {
  int x0 = 0, y0 = 0, x1 = fb.width, y1 = fb.height;  // [x0, x1) x [y0, y1)
  if (state.scissor.enabled) {
    x0 = std::clamp(state.scissor.x, 0, fb.width);
    y0 = std::clamp(state.scissor.y, 0, fb.height);
    x1 = std::clamp(state.scissor.x + state.scissor.width, x0, fb.width);
    y1 = std::clamp(state.scissor.y + state.scissor.height, y0, fb.height);
  }
  // glClear clears every draw buffer to the clear colour converted to its format (17.4.3:
  // sRGB-encoded where GL_FRAMEBUFFER_SRGB is on), depth to the clear depth in the depth format.
  if (color)
    for (int k = 0; k < fb.draw_buffers(); ++k) {
      std::vector<glm::vec4>* buffer = fb.draw_buffer(k);
      if (!buffer) continue;
      const glm::vec4 value = stored_color(fb.color_format[std::size_t(k)], state.framebuffer_srgb, *color);
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
          glm::vec4& p = (*buffer)[fb.index(x, y)];
          p = state.color_mask.apply(value, p);
        }
    }
  if (depth && state.depth_write) {  // glDepthMask, whether or not the test is on
    const float z = stored_depth(fb.depth_format, *depth);
    for (int y = y0; y < y1; ++y) std::fill_n(fb.depth.begin() + std::ptrdiff_t(fb.index(x0, y)), x1 - x0, z);
  }
}

}  // namespace tessref
