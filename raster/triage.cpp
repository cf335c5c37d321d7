#include "raster/triage.h"

#include "common/fixed_point.h"
#include "common/simd.h"

namespace tessref::raster {

// The lane loop: setup.cpp's kInside path for one triangle, without its branches. It mirrors
// piece_box (snapped area, culling, pixel_range) and store_piece's small-triangle coverage (edge.h,
// the fill rule included).
void triage_kernel_scalar(const TriageCorners& corners, int first, int n, const TriageParams& params,
                          std::uint8_t* out) {
  constexpr auto kMaxExtent = std::uint32_t(kTriageMaxExtent);
  const std::int32_t last_x = params.width - 1, last_y = params.height - 1;
  const bool front_cw = params.front_cw, cull_front = params.cull_front, cull_back = params.cull_back;
  for (int i = first; i < n; ++i) {
    std::int32_t x0 = corners.x[0][i], x1 = corners.x[1][i], x2 = corners.x[2][i];
    std::int32_t y0 = corners.y[0][i], y1 = corners.y[1][i], y2 = corners.y[2][i];
    const std::int32_t min_x = x0 < x1 ? (x0 < x2 ? x0 : x2) : (x1 < x2 ? x1 : x2);
    const std::int32_t max_x = x0 > x1 ? (x0 > x2 ? x0 : x2) : (x1 > x2 ? x1 : x2);
    const std::int32_t min_y = y0 < y1 ? (y0 < y2 ? y0 : y2) : (y1 < y2 ? y1 : y2);
    const std::int32_t max_y = y0 > y1 ? (y0 > y2 ? y0 : y2) : (y1 > y2 ? y1 : y2);
    // Lanes outside the fast path (clipped, or corners too far apart) compute on zeros instead of
    // what they hold (unset window fields, large values): no overflow, and the verdict is kSetUp.
    const bool ok = (corners.codes[i] == 0) & (std::uint32_t(max_x) - std::uint32_t(min_x) < kMaxExtent) &
                    (std::uint32_t(max_y) - std::uint32_t(min_y) < kMaxExtent);
    x0 = ok ? x0 : 0, x1 = ok ? x1 : 0, x2 = ok ? x2 : 0;
    y0 = ok ? y0 : 0, y1 = ok ? y1 : 0, y2 = ok ? y2 : 0;
    const std::int32_t area2 = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
    const bool ccw = area2 > 0;
    const bool front = ccw != front_cw;
    const bool culled = (area2 == 0) | (front & cull_front) | (!front & cull_back);
    // pixel_range: the centres k * 256 + 128 within [min, max], cut to the framebuffer.
    const std::int32_t lo_x = ok ? min_x : 0, hi_x = ok ? max_x : 0;
    const std::int32_t lo_y = ok ? min_y : 0, hi_y = ok ? max_y : 0;
    std::int32_t bx0 = (lo_x - 128 + 255) >> 8, bx1 = (hi_x - 128) >> 8;
    std::int32_t by0 = (lo_y - 128 + 255) >> 8, by1 = (hi_y - 128) >> 8;
    bx0 = bx0 < 0 ? 0 : bx0, by0 = by0 < 0 ? 0 : by0;
    bx1 = bx1 > last_x ? last_x : bx1, by1 = by1 > last_y ? last_y : by1;
    const bool empty = (bx0 > bx1) | (by0 > by1);
    const std::int32_t bw = bx1 - bx0 + 1, bh = by1 - by0 + 1;
    const std::int32_t cells = empty ? 0 : bw * bh;
    const bool small = !empty & (cells <= kSmallTrianglePixels);
    // Wound counter-clockwise as store_piece winds it: (v0, v1, v2) = (a, b, c) or (a, c, b).
    const std::int32_t v1x = ccw ? x1 : x2, v1y = ccw ? y1 : y2;
    const std::int32_t v2x = ccw ? x2 : x1, v2y = ccw ? y2 : y1;
    // Edge i runs from p_i to q_i (opposite vertex i): v1 -> v2, v2 -> v0, v0 -> v1.
    const std::int32_t px[3] = {v1x, v2x, x0}, py[3] = {v1y, v2y, y0};
    const std::int32_t qx[3] = {v2x, x0, v1x}, qy[3] = {v2y, y0, v1y};
    std::int32_t dx[3], dy[3], bias[3], row_e[3];
    const std::int32_t cx0 = bx0 * 256 + 128, cy0 = by0 * 256 + 128;
    for (int e = 0; e < 3; ++e) {
      dx[e] = qx[e] - px[e];
      dy[e] = qy[e] - py[e];
      bias[e] = fixed::is_top_left_edge(dx[e], dy[e]) ? 0 : -1;
      // E at the box's first centre (only read for small boxes, whose centres lie within 256 of
      // the corners' extent).
      row_e[e] = small ? dx[e] * (cy0 - py[e]) - dy[e] * (cx0 - px[e]) + bias[e] : 0;
    }
    // The box's centres in row order, as store_piece's small_mask bits.
    bool covers = false;
    std::int32_t col = 0;
    std::int32_t e0 = row_e[0], e1 = row_e[1], e2 = row_e[2];
    for (std::int32_t k = 0; k < kSmallTrianglePixels; ++k) {
      covers = covers | ((k < cells) & ((e0 | e1 | e2) >= 0));
      const bool wrap = col + 1 == bw;
      // Next centre: one to the right, or back to the row's start one row up.
      e0 += wrap ? dy[0] * 256 * col + dx[0] * 256 : -dy[0] * 256;
      e1 += wrap ? dy[1] * 256 * col + dx[1] * 256 : -dy[1] * 256;
      e2 += wrap ? dy[2] * 256 * col + dx[2] * 256 : -dy[2] * 256;
      col = wrap ? 0 : col + 1;
    }
    // kSetUp 0, kCulled 1, kNoFragment 2.
    const std::int32_t verdict = culled ? 1 : (empty | (small & !covers)) ? 2 : 0;
    out[i] = std::uint8_t(ok ? verdict : 0);
  }
}

void triage_triangles(const ProjectedVertex* projected, const std::uint32_t* indices, std::size_t first,
                      int n, const TriageParams& params, Triage* out) {
  thread_local TriageCorners corners;
  for (int k = 0; k < n; ++k) {
    std::uint32_t codes = 0;
    for (int c = 0; c < 3; ++c) {
      const std::size_t corner = 3 * (first + std::size_t(k)) + std::size_t(c);
      const ProjectedVertex& p = projected[indices ? indices[corner] : corner];
      corners.x[c][k] = p.x;
      corners.y[c][k] = p.y;
      codes |= p.code;
    }
    corners.codes[k] = codes;
  }
  static_assert(sizeof(Triage) == 1);
  auto* verdicts = reinterpret_cast<std::uint8_t*>(out);
  if (simd_path() == SimdPath::Avx2) triage_kernel_avx2(corners, n, params, verdicts);
  else triage_kernel_scalar(corners, 0, n, params, verdicts);
}

}  // namespace tessref::raster
