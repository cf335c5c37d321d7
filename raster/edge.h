#pragma once
// Edge functions in 24.8 fixed point, shared by setup (its small-triangle test), the binner and
// the tile scan, so that every place decides coverage by the same integers.
#include <cstdint>

#include "common/fixed_point.h"

namespace tessref::raster {

// Edge function of the directed edge a -> b at window point p, all 24.8:
// E(p) = dx (p.y - a.y) - dy (p.x - a.x), positive left of the edge (inside, for a CCW triangle).
// Values are in 16.16 and stay below 2^47 (see kMaxViewportPixels).
struct Edge {
  std::int64_t dx, dy;
  std::int64_t ax, ay;
  std::int64_t bias;    // fill rule: 0 on edges that own their centers, -1 elsewhere
  std::int64_t step_x;  // change of E for one pixel to the right: -dy * 256
  std::int64_t at(std::int64_t px, std::int64_t py) const {
    return dx * (py - ay) - dy * (px - ax);
  }
};

inline Edge make_edge(std::int32_t ax, std::int32_t ay, std::int32_t bx, std::int32_t by) {
  Edge e;
  e.dx = std::int64_t(bx) - ax;
  e.dy = std::int64_t(by) - ay;
  e.ax = ax;
  e.ay = ay;
  e.bias = fixed::is_top_left_edge(e.dx, e.dy) ? 0 : -1;
  e.step_x = -e.dy * fixed::kSubpixelOne;
  return e;
}

// The three edges of a counter-clockwise triangle; edge i is opposite vertex i, so E_i / area2
// is the barycentric weight of vertex i.
struct TriangleEdges {
  Edge e[3];
  TriangleEdges(const std::int32_t x[3], const std::int32_t y[3])
      : e{make_edge(x[1], y[1], x[2], y[2]), make_edge(x[2], y[2], x[0], y[0]),
          make_edge(x[0], y[0], x[1], y[1])} {}
};

}  // namespace tessref::raster
