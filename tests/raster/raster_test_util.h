#pragma once
// Shared helpers for the rasterizer tests: batches built from window coordinates and fragment
// programs that record what they see.
#include <atomic>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "raster/rasterizer.h"

namespace tessref::test {

// A clip-space vertex whose window position (for a W x H viewport, default depth range) is
// (wx, wy, wz), at clip w = w. With power-of-two viewports and dyadic inputs this is exact.
inline ClipVertex window_vertex(float wx, float wy, float wz, int width, int height,
                                float w = 1.0f) {
  ClipVertex v;
  const float x_ndc = 2.0f * wx / float(width) - 1.0f;
  const float y_ndc = 2.0f * wy / float(height) - 1.0f;
  const float z_ndc = 2.0f * wz - 1.0f;
  v.position = glm::vec4(x_ndc * w, y_ndc * w, z_ndc * w, w);
  return v;
}

inline void add_triangle(TriangleBatch& b, const ClipVertex& a, const ClipVertex& c0,
                         const ClipVertex& c1) {
  b.vertices.push_back(a);
  b.vertices.push_back(c0);
  b.vertices.push_back(c1);
}

// Counts every shaded fragment per pixel. Atomic, because tiles run on many threads.
struct CountingProgram : FragmentProgram {
  int width;
  std::unique_ptr<std::atomic<std::uint32_t>[]> counts;
  CountingProgram(int w, int h)
      : width(w), counts(new std::atomic<std::uint32_t>[std::size_t(w) * h]) {
    for (std::size_t i = 0; i < std::size_t(w) * h; ++i) counts[i] = 0;
  }
  FragmentOutput shade(const FragmentInput& in) const override {
    const int x = int(in.frag_coord.x), y = int(in.frag_coord.y);
    counts[std::size_t(y) * width + x].fetch_add(1, std::memory_order_relaxed);
    return {};
  }
  std::uint32_t at(int x, int y) const { return counts[std::size_t(y) * width + x].load(); }
};

// Writes the first four varyings to color and (frag_coord.w, front_facing, 0, 0) to aux.
struct VaryingProgram : FragmentProgram {
  FragmentOutput shade(const FragmentInput& in) const override {
    FragmentOutput o;
    o.color = glm::vec4(in.varyings[0], in.varyings[1], in.varyings[2], in.varyings[3]);
    o.aux = glm::vec4(in.frag_coord.w, in.front_facing ? 1.0f : 0.0f, 0.0f, 0.0f);
    return o;
  }
};

// Gives every triangle of `b` its own constant window depth, strictly decreasing in submission
// order, so that with depth test LESS every fragment passes: a way to count raw coverage.
inline void make_depth_decreasing(TriangleBatch& b) {
  const std::size_t n = b.triangle_count();
  for (std::size_t t = 0; t < n; ++t) {
    const float z_ndc = 0.9f - 1.8f * float(t + 1) / float(n + 1);
    for (int k = 0; k < 3; ++k) {
      glm::vec4& p = b.vertices[3 * t + k].position;
      p.z = z_ndc * p.w;
    }
  }
}

}  // namespace tessref::test
