#include "raster/line_setup.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "common/fixed_point.h"

namespace tessref::raster {
namespace {

// llvmpipe's subpixel_snap: round to nearest (even) of 256 a.
std::int32_t snap(float a) { return fixed::snap_subpixel(a); }

// GL's half-pixel centers: llvmpipe snaps x_w - 0.5 (its pixel_offset), so that pixel centers are
// whole numbers in the snapped space.
constexpr float kPixelOffset = 0.5f;

bool non_negative(float x) { return x >= 0.0f; }
float frac(float f) { return f - std::floor(f); }  // used on positive values, as llvmpipe does

// The box of candidate pixels from the four snapped corners (llvmpipe's bounding rectangle with
// the top-left rule: X is a candidate when 256 X lies in [min x, max x)), cut to the viewport.
bool candidate_box(const std::int32_t x[4], const std::int32_t y[4], const Viewport& vp,
                   SetupTriangle& t) {
  const std::int32_t one = fixed::kSubpixelOne;
  t.min_x = std::max(0, (std::min({x[0], x[1], x[2], x[3]}) + one - 1) >> fixed::kSubpixelBits);
  t.max_x = std::min(vp.width - 1,
                     ((std::max({x[0], x[1], x[2], x[3]}) + one - 1) >> fixed::kSubpixelBits) - 1);
  t.min_y = std::max(0, (std::min({y[0], y[1], y[2], y[3]}) + one - 1) >> fixed::kSubpixelBits);
  t.max_y = std::min(vp.height - 1,
                     ((std::max({y[0], y[1], y[2], y[3]}) + one - 1) >> fixed::kSubpixelBits) - 1);
  return t.min_x <= t.max_x && t.min_y <= t.max_y;
}

// Plane i runs from corner i to corner i + 1; the fill rule owns left edges (dcdx < 0) and, of
// horizontal ones, those with dcdy < 0 (Mesa 22.3's line setup picks its "bottom-left" variant
// from the half-pixel offset GL uses, whatever the triangle rule).
void make_planes(const std::int32_t x[4], const std::int32_t y[4], HalfPlane plane[4]) {
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    HalfPlane& p = plane[i];
    p.dcdx = std::int64_t(y[i]) - y[j];
    p.dcdy = std::int64_t(x[i]) - x[j];
    p.c = p.dcdx * x[i] - p.dcdy * y[i];
    if (p.dcdx < 0 || (p.dcdx == 0 && p.dcdy > 0)) ++p.c;
  }
}

void store_varyings(const LineVertex& a, const LineVertex& b, int num_varyings,
                    const VaryingMask* flat, SetupTriangle& t, std::vector<float>& varyings) {
  t.varying_offset = std::uint32_t(varyings.size());
  varyings.resize(varyings.size() + 3 * std::size_t(num_varyings));
  float* out = varyings.data() + t.varying_offset;
  for (int j = 0; j < num_varyings; ++j) {
    const bool is_flat = flat && (*flat)[std::size_t(j)];
    out[j] = is_flat ? b.varyings[j] : a.varyings[j];
    out[num_varyings + j] = is_flat ? 0.0f : b.varyings[j] - a.varyings[j];
    out[2 * num_varyings + j] = 0.0f;
  }
}

void common_fields(const LineVertex& a, const LineVertex& b, const Viewport& vp,
                   SetupTriangle& t) {
  const LineVertex* v[3] = {&a, &b, &a};
  for (int i = 0; i < 3; ++i) {
    t.x[i] = snap(v[i]->x);
    t.y[i] = snap(v[i]->y);
    t.z[i] = v[i]->z;
    t.inv_w[i] = v[i]->inv_w;
  }
  t.front_facing = true;  // GL: points and lines are front-facing
  t.small_mask = 0;
  t.b_x0 = a.x;
  t.b_y0 = a.y;
  t.b1_dx = t.b1_dy = t.b2_dx = t.b2_dy = 0.0;
  t.z_lo = vp.vertex_z_lo();
  t.z_hi = vp.vertex_z_hi();
}

}  // namespace

bool setup_line(const LineVertex& a, const LineVertex& b, const Viewport& vp, int num_varyings,
                const VaryingMask* flat, std::vector<SetupQuad>& quads,
                std::vector<float>& varyings) {
  // llvmpipe's v1, v2 are a, b; it swaps its pointers below, the attribute planes keep a -> b.
  const LineVertex* v1 = &a;
  const LineVertex* v2 = &b;
  const float dx = v1->x - v2->x;
  const float dy = v1->y - v2->y;
  if (dx * dx + dy * dy == 0.0f) return false;  // zero length: nothing drawn

  float x_offset = 0.0f, y_offset = 0.0f, x_offset_end = 0.0f, y_offset_end = 0.0f;
  float x1diff = v1->x - std::floor(v1->x) - 0.5f;
  float y1diff = v1->y - std::floor(v1->y) - 0.5f;
  float x2diff = v2->x - std::floor(v2->x) - 0.5f;
  float y2diff = v2->y - std::floor(v2->y) - 0.5f;
  constexpr std::int32_t kHalfWidth = fixed::kSubpixelOne / 2;  // line width 1
  std::int32_t x[4], y[4];
  const bool x_major = std::fabs(dx) >= std::fabs(dy);
  // GL 4.6 section 14.5.1 ("diamond-exit"): a pixel is drawn when the segment exits its diamond
  // |x - x_c| + |y - y_c| < 1/2; the start point's diamond counts if the segment leaves it, the
  // end point's does not. llvmpipe decides both ends from the endpoints' offsets inside their
  // pixels and moves the quad's ends by up to half a pixel along the major axis.
  // The offsets are computed in double and stored as float, as llvmpipe's C does (0.5 is a double).
  auto offset = [](float diff, double half) { return float(-double(diff) + half); };
  if (x_major) {
    const float dydx = dy / dx;
    if (y2diff == -0.5f && dy < 0.0f) y2diff = 0.5f;
    bool draw_start, draw_end;
    if (std::fabs(x1diff) + std::fabs(y1diff) < 0.5f) draw_start = true;
    else if (non_negative(x1diff) == non_negative(-dx)) draw_start = false;
    else if (non_negative(-y1diff) != non_negative(dy)) draw_start = true;
    else {
      const float yintersect = frac(v1->y) + x1diff * dydx;
      draw_start = yintersect < 1.0f && yintersect > 0.0f;
    }
    if (std::fabs(x2diff) + std::fabs(y2diff) < 0.5f) draw_end = false;
    else if (non_negative(x2diff) != non_negative(-dx)) draw_end = false;
    else if (non_negative(-y2diff) == non_negative(dy)) draw_end = true;
    else {
      const float yintersect = frac(v2->y) + x2diff * dydx;
      draw_end = yintersect < 1.0f && yintersect > 0.0f;
    }
    // Whether the quad, ending at the endpoints, already covers the end pixels.
    const bool will_draw_start = non_negative(-x1diff) != non_negative(dx);
    const bool will_draw_end = non_negative(x2diff) == non_negative(-dx) || x2diff == 0.0f;
    if (dx < 0.0f) {
      std::swap(v1, v2);  // v1 becomes the right end
      if (will_draw_start != draw_start) {
        x_offset_end = offset(x1diff, -0.5);
        y_offset_end = x_offset_end * dydx;
      }
      if (will_draw_end != draw_end) {
        x_offset = offset(x2diff, -0.5);
        y_offset = x_offset * dydx;
      }
    } else {
      if (will_draw_start != draw_start) {
        x_offset = offset(x1diff, 0.5);
        y_offset = x_offset * dydx;
      }
      if (will_draw_end != draw_end) {
        x_offset_end = offset(x2diff, 0.5);
        y_offset_end = x_offset_end * dydx;
      }
    }
    x[0] = snap(v1->x + x_offset - kPixelOffset);
    x[1] = snap(v2->x + x_offset_end - kPixelOffset);
    x[2] = x[1];
    x[3] = x[0];
    y[0] = snap(v1->y + y_offset - kPixelOffset) - kHalfWidth;
    y[1] = snap(v2->y + y_offset_end - kPixelOffset) - kHalfWidth;
    y[2] = snap(v2->y + y_offset_end - kPixelOffset) + kHalfWidth;
    y[3] = snap(v1->y + y_offset - kPixelOffset) + kHalfWidth;
  } else {
    const float dxdy = dx / dy;
    if (x2diff == -0.5f && dx < 0.0f) x2diff = 0.5f;
    bool draw_start, draw_end;
    if (std::fabs(x1diff) + std::fabs(y1diff) < 0.5f) draw_start = true;
    else if (non_negative(-y1diff) == non_negative(dy)) draw_start = false;
    else if (non_negative(x1diff) != non_negative(-dx)) draw_start = true;
    else {
      const float xintersect = frac(v1->x) + y1diff * dxdy;
      draw_start = xintersect < 1.0f && xintersect > 0.0f;
    }
    if (std::fabs(x2diff) + std::fabs(y2diff) < 0.5f) draw_end = false;
    else if (non_negative(-y2diff) != non_negative(dy)) draw_end = false;
    else if (non_negative(x2diff) == non_negative(-dx)) draw_end = true;
    else {
      const float xintersect = frac(v2->x) + y2diff * dxdy;
      draw_end = xintersect < 1.0f && xintersect >= 0.0f;
    }
    const bool will_draw_start = non_negative(y1diff) == non_negative(dy);
    const bool will_draw_end = non_negative(-y2diff) == non_negative(dy) || y2diff == 0.0f;
    if (dy > 0.0f) {
      std::swap(v1, v2);  // v1 becomes the lower end (smaller y)
      if (will_draw_start != draw_start) {
        y_offset_end = offset(y1diff, 0.5);
        x_offset_end = y_offset_end * dxdy;
      }
      if (will_draw_end != draw_end) {
        y_offset = offset(y2diff, 0.5);
        x_offset = y_offset * dxdy;
      }
    } else {
      if (will_draw_start != draw_start) {
        y_offset = offset(y1diff, -0.5);
        x_offset = y_offset * dxdy;
      }
      if (will_draw_end != draw_end) {
        y_offset_end = offset(y2diff, -0.5);
        x_offset_end = y_offset_end * dxdy;
      }
    }
    x[0] = snap(v1->x + x_offset - kPixelOffset) - kHalfWidth;
    x[1] = snap(v2->x + x_offset_end - kPixelOffset) - kHalfWidth;
    x[2] = snap(v2->x + x_offset_end - kPixelOffset) + kHalfWidth;
    x[3] = snap(v1->x + x_offset - kPixelOffset) + kHalfWidth;
    y[0] = snap(v1->y + y_offset - kPixelOffset);
    y[1] = snap(v2->y + y_offset_end - kPixelOffset);
    y[2] = y[1];
    y[3] = y[0];
  }

  SetupQuad q;
  if (!candidate_box(x, y, vp, q.t)) return false;
  make_planes(x, y, q.plane);
  common_fields(a, b, vp, q.t);
  // Attributes vary along the major axis only (llvmpipe's "preferred wide-lines formula"): the
  // weight of b is the fraction of the way from a to b in x (x-major) or y.
  if (x_major) q.t.b1_dx = 1.0 / (double(b.x) - double(a.x));
  else q.t.b1_dy = 1.0 / (double(b.y) - double(a.y));
  store_varyings(a, b, num_varyings, flat, q.t, varyings);
  quads.push_back(q);
  return true;
}

bool setup_point(const LineVertex& p, const Viewport& vp, int num_varyings,
                 std::vector<SetupQuad>& quads, std::vector<float>& varyings) {
  constexpr std::int32_t kWidth = fixed::kSubpixelOne;  // size 1
  const std::int32_t x0 = snap(p.x - kPixelOffset) - kWidth / 2;
  const std::int32_t y0 = snap(p.y - kPixelOffset) - kWidth / 2;
  const std::int32_t x[4] = {x0, x0 + kWidth, x0 + kWidth, x0};
  const std::int32_t y[4] = {y0, y0, y0 + kWidth, y0 + kWidth};
  SetupQuad q;
  if (!candidate_box(x, y, vp, q.t)) return false;
  // The square's sides as half-planes: 256 X >= x0, 256 X < x0 + 256, and the same in y (left and
  // bottom sides inclusive).
  q.plane[0] = {-std::int64_t(x0) + 1, -1, 0};
  q.plane[1] = {std::int64_t(x0) + kWidth, 1, 0};
  q.plane[2] = {-std::int64_t(y0) + 1, 0, 1};
  q.plane[3] = {std::int64_t(y0) + kWidth, 0, -1};
  common_fields(p, p, vp, q.t);
  store_varyings(p, p, num_varyings, nullptr, q.t, varyings);
  quads.push_back(q);
  return true;
}

}  // namespace tessref::raster
