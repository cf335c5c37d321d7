#include "raster/tile_raster.h"

#include <algorithm>

#include "common/fixed_point.h"

namespace tessref::raster {
namespace {

// Edge function of the directed edge a -> b at window point p, all 24.8:
// E(p) = dx (p.y - a.y) - dy (p.x - a.x), positive left of the edge (inside, for a CCW triangle).
// Values are in 16.16 and stay below 2^47 (see kMaxViewportPixels).
struct Edge {
  std::int64_t dx, dy;
  std::int64_t ax, ay;
  std::int64_t bias;  // fill convention correction: 0 on top/left edges, -1 elsewhere
  std::int64_t at(std::int64_t px, std::int64_t py) const { return dx * (py - ay) - dy * (px - ax); }
};

Edge make_edge(std::int32_t ax, std::int32_t ay, std::int32_t bx, std::int32_t by) {
  Edge e;
  e.dx = std::int64_t(bx) - ax;
  e.dy = std::int64_t(by) - ay;
  e.ax = ax;
  e.ay = ay;
  e.bias = fixed::is_top_left_edge(e.dx, e.dy) ? 0 : -1;
  return e;
}

// floor(a / b) and ceil(a / b) for b > 0.
std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  std::int64_t q = a / b;
  return (a % b != 0 && a < 0) ? q - 1 : q;
}
std::int64_t ceil_div(std::int64_t a, std::int64_t b) { return -floor_div(-a, b); }

}  // namespace

std::uint64_t raster_triangle(const SetupTriangle& t, const float* varyings, int num_varyings,
                              const PixelRect& rect, const FragmentProgram& fs, Framebuffer& fb) {
  const int x0 = std::max(rect.x0, t.min_x), x1 = std::min(rect.x1, t.max_x);
  const int y0 = std::max(rect.y0, t.min_y), y1 = std::min(rect.y1, t.max_y);
  if (x0 > x1 || y0 > y1) return 0;

  // Edge i is opposite vertex i, so E_i / area2 is the barycentric weight of vertex i.
  const Edge edges[3] = {make_edge(t.x[1], t.y[1], t.x[2], t.y[2]),
                         make_edge(t.x[2], t.y[2], t.x[0], t.y[0]),
                         make_edge(t.x[0], t.y[0], t.x[1], t.y[1])};
  const std::int64_t step = fixed::kSubpixelOne;
  const double dz1 = double(t.z[1]) - t.z[0];
  const double dz2 = double(t.z[2]) - t.z[0];
  const bool write_aux = !fb.aux.empty();

  float frag_varyings[kMaxVaryings] = {};  // slots past num_varyings read as 0
  FragmentInput in;
  in.front_facing = t.front_facing;
  in.varyings = frag_varyings;

  std::uint64_t shaded = 0;
  const std::int64_t px0 = fixed::pixel_center(x0);
  for (int y = y0; y <= y1; ++y) {
    const std::int64_t py = fixed::pixel_center(y);
    // Exact span of this row: E_i(x0 + k) + bias_i = row_i - k * dy_i * 256 >= 0 for all i.
    std::int64_t row[3];
    std::int64_t k_lo = 0, k_hi = x1 - x0;
    for (int i = 0; i < 3; ++i) {
      row[i] = edges[i].at(px0, py);
      const std::int64_t c = row[i] + edges[i].bias;  // need c - k * s >= 0
      const std::int64_t s = edges[i].dy * step;
      if (s == 0) {
        if (c < 0) k_hi = -1;
      } else if (s > 0) {
        k_hi = std::min(k_hi, floor_div(c, s));
      } else {
        k_lo = std::max(k_lo, ceil_div(-c, -s));
      }
    }
    if (k_lo > k_hi) continue;

    std::int64_t e[3];
    for (int i = 0; i < 3; ++i) e[i] = row[i] - k_lo * edges[i].dy * step;
    const float fy = float(y) + 0.5f;
    for (std::int64_t k = k_lo; k <= k_hi; ++k) {
      const int x = x0 + int(k);
      const std::size_t idx = fb.index(x, y);
      const double b0 = double(e[0]) * t.inv_area2;
      const double b1 = double(e[1]) * t.inv_area2;
      const double b2 = double(e[2]) * t.inv_area2;
      for (int i = 0; i < 3; ++i) e[i] -= edges[i].dy * step;

      // Window depth is linear in window space.
      const float z = float(double(t.z[0]) + b1 * dz1 + b2 * dz2);
      if (!(z < fb.depth[idx])) continue;

      // Perspective correction: interpolate attribute/w and 1/w linearly, then divide.
      const double p0 = b0 * t.inv_w[0], p1 = b1 * t.inv_w[1], p2 = b2 * t.inv_w[2];
      const double inv_w = p0 + p1 + p2;
      const float w1 = float(p1 / inv_w), w2 = float(p2 / inv_w);
      const float* a0 = varyings;
      const float* a1 = varyings + num_varyings;
      const float* a2 = varyings + 2 * num_varyings;
      // Relative to vertex 0, so that a varying equal at all three vertices stays exact.
      for (int j = 0; j < num_varyings; ++j)
        frag_varyings[j] = a0[j] + w1 * (a1[j] - a0[j]) + w2 * (a2[j] - a0[j]);

      in.frag_coord = glm::vec4(float(x) + 0.5f, fy, z, float(inv_w));
      const FragmentOutput out = fs.shade(in);
      fb.depth[idx] = z;
      fb.color[idx] = out.color;
      if (write_aux) fb.aux[idx] = out.aux;
      ++shaded;
    }
  }
  return shaded;
}

}  // namespace tessref::raster
