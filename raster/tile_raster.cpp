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
  std::int64_t bias;    // fill rule: 0 on edges that own their centers, -1 elsewhere
  std::int64_t step_x;  // change of E for one pixel to the right: -dy * 256
  std::int64_t at(std::int64_t px, std::int64_t py) const {
    return dx * (py - ay) - dy * (px - ax);
  }
};

Edge make_edge(std::int32_t ax, std::int32_t ay, std::int32_t bx, std::int32_t by) {
  Edge e;
  e.dx = std::int64_t(bx) - ax;
  e.dy = std::int64_t(by) - ay;
  e.ax = ax;
  e.ay = ay;
  e.bias = fixed::is_top_left_edge(e.dx, e.dy) ? 0 : -1;
  e.step_x = -e.dy * fixed::kSubpixelOne;
  return e;
}

// floor(a / b) and ceil(a / b) for b > 0.
std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  std::int64_t q = a / b;
  return (a % b != 0 && a < 0) ? q - 1 : q;
}
std::int64_t ceil_div(std::int64_t a, std::int64_t b) { return -floor_div(-a, b); }

// Rows narrower than this are scanned pixel by pixel; wider ones get their exact span by
// division first (three 64-bit divisions cost about as much as a dozen pixel tests).
constexpr int kSpanDivisionMinWidth = 12;

// Everything per triangle that the per-fragment work reads.
struct Interpolator {
  const SetupTriangle& t;
  const float* varyings;  // a0, a1 - a0, a2 - a0; num_varyings each
  int num_varyings;
  double dz1, dz2;
  double inv_w0, inv_w1, inv_w2;
  const FragmentProgram& fs;
  Framebuffer& fb;
  bool write_aux;

  // Depth test, then perspective-correct varyings and the shader, for the center of (x, y).
  // Returns whether the fragment was shaded.
  bool fragment(int x, int y, std::size_t idx, float* frag_varyings, FragmentInput& in) const {
    // Barycentrics from the planes through the float positions (see SetupTriangle); window
    // depth is linear in window space.
    const double dx = double(x) + 0.5 - t.b_x0, dy = double(y) + 0.5 - t.b_y0;
    const double b1 = t.b1_dx * dx + t.b1_dy * dy;
    const double b2 = t.b2_dx * dx + t.b2_dy * dy;
    const float z = std::clamp(float(double(t.z[0]) + b1 * dz1 + b2 * dz2), t.z_lo, t.z_hi);
    if (!(z < fb.depth[idx])) return false;

    // Perspective correction: interpolate attribute/w and 1/w linearly, then divide.
    const double b0 = 1.0 - b1 - b2;
    const double p0 = b0 * inv_w0, p1 = b1 * inv_w1, p2 = b2 * inv_w2;
    const double inv_w = p0 + p1 + p2;
    const double w = 1.0 / inv_w;
    const float w1 = float(p1 * w), w2 = float(p2 * w);
    const float* __restrict a0 = varyings;
    const float* __restrict d1 = varyings + num_varyings;
    const float* __restrict d2 = varyings + 2 * num_varyings;
    // Relative to vertex 0, so that a varying equal at all three vertices stays exact.
    for (int j = 0; j < num_varyings; ++j) frag_varyings[j] = a0[j] + w1 * d1[j] + w2 * d2[j];

    in.frag_coord = glm::vec4(float(x) + 0.5f, float(y) + 0.5f, z, float(inv_w));
    const FragmentOutput out = fs.shade(in);
    fb.depth[idx] = z;
    fb.color[idx] = out.color;
    if (write_aux) fb.aux[idx] = out.aux;
    return true;
  }
};

}  // namespace

bool triangle_may_cover(const SetupTriangle& t, const PixelRect& rect) {
  const Edge edges[3] = {make_edge(t.x[1], t.y[1], t.x[2], t.y[2]),
                         make_edge(t.x[2], t.y[2], t.x[0], t.y[0]),
                         make_edge(t.x[0], t.y[0], t.x[1], t.y[1])};
  const std::int64_t cx0 = fixed::pixel_center(rect.x0), cx1 = fixed::pixel_center(rect.x1);
  const std::int64_t cy0 = fixed::pixel_center(rect.y0), cy1 = fixed::pixel_center(rect.y1);
  for (const Edge& e : edges) {
    // E is linear, so its largest value over the rectangle of centers is at a corner.
    const std::int64_t best = std::max(std::max(e.at(cx0, cy0), e.at(cx1, cy0)),
                                       std::max(e.at(cx0, cy1), e.at(cx1, cy1)));
    if (best + e.bias < 0) return false;
  }
  return true;
}

std::uint64_t raster_triangle(const SetupTriangle& t, const float* varyings, int num_varyings,
                              const PixelRect& rect, const FragmentProgram& fs, Framebuffer& fb) {
  const int x0 = std::max(rect.x0, t.min_x), x1 = std::min(rect.x1, t.max_x);
  const int y0 = std::max(rect.y0, t.min_y), y1 = std::min(rect.y1, t.max_y);
  if (x0 > x1 || y0 > y1) return 0;

  // Edge i is opposite vertex i, so E_i / area2 is the barycentric weight of vertex i.
  const Edge edges[3] = {make_edge(t.x[1], t.y[1], t.x[2], t.y[2]),
                         make_edge(t.x[2], t.y[2], t.x[0], t.y[0]),
                         make_edge(t.x[0], t.y[0], t.x[1], t.y[1])};
  const Interpolator interp{t,
                            varyings,
                            num_varyings,
                            double(t.z[1]) - t.z[0],
                            double(t.z[2]) - t.z[0],
                            t.inv_w[0],
                            t.inv_w[1],
                            t.inv_w[2],
                            fs,
                            fb,
                            !fb.aux.empty()};

  float frag_varyings[kMaxVaryings] = {};  // slots past num_varyings read as 0
  FragmentInput in;
  in.front_facing = t.front_facing;
  in.varyings = frag_varyings;

  std::uint64_t shaded = 0;
  const std::int64_t px0 = fixed::pixel_center(x0);
  const bool divide = x1 - x0 + 1 >= kSpanDivisionMinWidth;
  for (int y = y0; y <= y1; ++y) {
    const std::int64_t py = fixed::pixel_center(y);
    std::int64_t e[3];
    for (int i = 0; i < 3; ++i) e[i] = edges[i].at(px0, py);
    const std::size_t row = fb.index(x0, y);

    if (!divide) {
      // Inside iff E_i + bias_i >= 0 for all i, i.e. (E + bias) has no sign bit in any edge.
      for (int x = x0; x <= x1; ++x) {
        if (((e[0] + edges[0].bias) | (e[1] + edges[1].bias) | (e[2] + edges[2].bias)) >= 0)
          shaded += interp.fragment(x, y, row + (x - x0), frag_varyings, in);
        for (int i = 0; i < 3; ++i) e[i] += edges[i].step_x;
      }
      continue;
    }

    // Exact span of this row: E_i(x0 + k) + bias_i = e_i + bias_i + k * step_i >= 0 for all i.
    std::int64_t k_lo = 0, k_hi = x1 - x0;
    for (int i = 0; i < 3; ++i) {
      const std::int64_t c = e[i] + edges[i].bias;
      const std::int64_t s = edges[i].step_x;
      if (s == 0) {
        if (c < 0) k_hi = -1;
      } else if (s < 0) {
        k_hi = std::min(k_hi, floor_div(c, -s));
      } else {
        k_lo = std::max(k_lo, ceil_div(-c, s));
      }
    }
    if (k_lo > k_hi) continue;
    for (int i = 0; i < 3; ++i) e[i] += k_lo * edges[i].step_x;
    for (std::int64_t k = k_lo; k <= k_hi; ++k) {
      shaded += interp.fragment(x0 + int(k), y, row + std::size_t(k), frag_varyings, in);
      for (int i = 0; i < 3; ++i) e[i] += edges[i].step_x;
    }
  }
  return shaded;
}

}  // namespace tessref::raster
