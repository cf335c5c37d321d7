#pragma once
// What the coverage comparisons against llvmpipe (raster_vs_llvmpipe_test, lines_vs_llvmpipe_test)
// share: window positions as clip positions, and a fragment program that records which primitive
// ids shaded each pixel.
#include <atomic>
#include <cstdint>
#include <memory>

#include <glm/glm.hpp>

#include "raster/rasterizer.h"

namespace tessref::test {

// Window (x, y, depth) -> clip position with w = 1 for a w x h viewport and depth range [0, 1].
// Exact for the dyadic coordinates used here (power-of-two viewports, 1/256 grid).
inline glm::vec4 clip_from_window(glm::vec3 p, int w, int h) {
  return glm::vec4(float(2.0 * double(p.x) / w - 1.0), float(2.0 * double(p.y) / h - 1.0),
                   float(2.0 * double(p.z) - 1.0), 1.0f);
}

// Records, per pixel, the set of primitive ids (varying 0, below 192) that shaded it; color gets
// the id and gl_FragCoord.
struct MaskProgram : FragmentProgram {
  int width;
  std::unique_ptr<std::atomic<std::uint64_t>[]> mask;
  MaskProgram(int w, int h) : width(w), mask(new std::atomic<std::uint64_t>[3 * std::size_t(w) * h]) {
    for (std::size_t i = 0; i < 3 * std::size_t(w) * h; ++i) mask[i] = 0;
  }
  FragmentOutput shade(const FragmentInput& in) const override {
    const int id = int(in.varyings[0]);
    const std::size_t px = std::size_t(int(in.frag_coord.y)) * width + int(in.frag_coord.x);
    mask[3 * px + id / 64].fetch_or(std::uint64_t(1) << (id % 64), std::memory_order_relaxed);
    FragmentOutput o;
    o.color = glm::vec4(float(id), in.frag_coord.x, in.frag_coord.y, in.frag_coord.z);
    return o;
  }
};

}  // namespace tessref::test
