// The AVX2 build of the triage kernel, 8 triangles at a time (this file alone is compiled with
// -mavx2). Operation for operation triage.cpp's lane loop, in 32-bit integers, so the
// verdicts are the scalar build's (tests/raster/triage_test.cpp compares them).
#include <immintrin.h>

#include "raster/triage.h"

namespace tessref::raster {
namespace {

__m256i select(__m256i mask, __m256i a, __m256i b) { return _mm256_blendv_epi8(b, a, mask); }
__m256i min3(__m256i a, __m256i b, __m256i c) { return _mm256_min_epi32(_mm256_min_epi32(a, b), c); }
__m256i max3(__m256i a, __m256i b, __m256i c) { return _mm256_max_epi32(_mm256_max_epi32(a, b), c); }
__m256i mul(__m256i a, __m256i b) { return _mm256_mullo_epi32(a, b); }
__m256i sub(__m256i a, __m256i b) { return _mm256_sub_epi32(a, b); }
__m256i add(__m256i a, __m256i b) { return _mm256_add_epi32(a, b); }
__m256i gt(__m256i a, __m256i b) { return _mm256_cmpgt_epi32(a, b); }
__m256i eq(__m256i a, __m256i b) { return _mm256_cmpeq_epi32(a, b); }
__m256i set1(std::int32_t v) { return _mm256_set1_epi32(v); }
__m256i load(const std::int32_t* p) { return _mm256_load_si256(reinterpret_cast<const __m256i*>(p)); }

}  // namespace

void triage_kernel_avx2(const TriageCorners& corners, int n, const TriageParams& params,
                        std::uint8_t* out) {
  const __m256i zero = _mm256_setzero_si256(), ones = set1(-1);
  const __m256i last_x = set1(params.width - 1), last_y = set1(params.height - 1);
  const __m256i extent_limit = set1(kTriageMaxExtent);
  const __m256i front_cw = set1(params.front_cw ? -1 : 0);
  const __m256i cull_front = set1(params.cull_front ? -1 : 0), cull_back = set1(params.cull_back ? -1 : 0);
  const __m256i c128 = set1(128), c127 = set1(127), c256 = set1(256), small_pixels = set1(kSmallTrianglePixels);
  int i = 0;
  for (; i + 8 <= n; i += 8) {
    __m256i x0 = load(&corners.x[0][i]), x1 = load(&corners.x[1][i]), x2 = load(&corners.x[2][i]);
    __m256i y0 = load(&corners.y[0][i]), y1 = load(&corners.y[1][i]), y2 = load(&corners.y[2][i]);
    const __m256i codes = load(reinterpret_cast<const std::int32_t*>(&corners.codes[i]));
    const __m256i min_x = min3(x0, x1, x2), max_x = max3(x0, x1, x2);
    const __m256i min_y = min3(y0, y1, y2), max_y = max3(y0, y1, y2);
    // Unsigned max - min < kTriageMaxExtent: as signed, (max - min) in [0, kTriageMaxExtent).
    const __m256i ext_x = sub(max_x, min_x), ext_y = sub(max_y, min_y);
    const __m256i in_x = _mm256_andnot_si256(gt(zero, ext_x), gt(extent_limit, ext_x));
    const __m256i in_y = _mm256_andnot_si256(gt(zero, ext_y), gt(extent_limit, ext_y));
    const __m256i ok = _mm256_and_si256(eq(codes, zero), _mm256_and_si256(in_x, in_y));
    x0 = _mm256_and_si256(ok, x0), x1 = _mm256_and_si256(ok, x1), x2 = _mm256_and_si256(ok, x2);
    y0 = _mm256_and_si256(ok, y0), y1 = _mm256_and_si256(ok, y1), y2 = _mm256_and_si256(ok, y2);
    const __m256i area2 = sub(mul(sub(x1, x0), sub(y2, y0)), mul(sub(x2, x0), sub(y1, y0)));
    const __m256i ccw = gt(area2, zero);
    const __m256i front = _mm256_xor_si256(ccw, front_cw);
    const __m256i culled = _mm256_or_si256(
        eq(area2, zero), _mm256_or_si256(_mm256_and_si256(front, cull_front),
                                         _mm256_andnot_si256(front, cull_back)));
    const __m256i lo_x = _mm256_and_si256(ok, min_x), hi_x = _mm256_and_si256(ok, max_x);
    const __m256i lo_y = _mm256_and_si256(ok, min_y), hi_y = _mm256_and_si256(ok, max_y);
    const __m256i bx0 = _mm256_max_epi32(_mm256_srai_epi32(add(lo_x, c127), 8), zero);
    const __m256i by0 = _mm256_max_epi32(_mm256_srai_epi32(add(lo_y, c127), 8), zero);
    const __m256i bx1 = _mm256_min_epi32(_mm256_srai_epi32(sub(hi_x, c128), 8), last_x);
    const __m256i by1 = _mm256_min_epi32(_mm256_srai_epi32(sub(hi_y, c128), 8), last_y);
    const __m256i empty = _mm256_or_si256(gt(bx0, bx1), gt(by0, by1));
    const __m256i bw = sub(bx1, sub(bx0, set1(1)));
    const __m256i cells = _mm256_andnot_si256(empty, mul(bw, sub(by1, sub(by0, set1(1)))));
    const __m256i small = _mm256_andnot_si256(empty, _mm256_xor_si256(gt(cells, small_pixels), ones));
    const __m256i v1x = select(ccw, x1, x2), v1y = select(ccw, y1, y2);
    const __m256i v2x = select(ccw, x2, x1), v2y = select(ccw, y2, y1);
    const __m256i px[3] = {v1x, v2x, x0}, py[3] = {v1y, v2y, y0};
    const __m256i qx[3] = {v2x, x0, v1x}, qy[3] = {v2y, y0, v1y};
    const __m256i cx0 = add(_mm256_slli_epi32(bx0, 8), c128), cy0 = add(_mm256_slli_epi32(by0, 8), c128);
    __m256i dx[3], dy[3], e[3];
    for (int k = 0; k < 3; ++k) {
      dx[k] = sub(qx[k], px[k]);
      dy[k] = sub(qy[k], py[k]);
      // bias 0 on top-left edges (dy < 0, or dy == 0 and dx > 0), else -1.
      const __m256i top_left = _mm256_or_si256(gt(zero, dy[k]), _mm256_and_si256(eq(dy[k], zero), gt(dx[k], zero)));
      const __m256i bias = _mm256_xor_si256(top_left, ones);  // -1 where not top-left
      e[k] = _mm256_and_si256(small, add(sub(mul(dx[k], sub(cy0, py[k])), mul(dy[k], sub(cx0, px[k]))), bias));
    }
    __m256i covers = zero, col = zero;
    for (int k = 0; k < kSmallTrianglePixels; ++k) {
      const __m256i outside = gt(zero, _mm256_or_si256(_mm256_or_si256(e[0], e[1]), e[2]));  // a sign bit
      covers = _mm256_or_si256(covers, _mm256_andnot_si256(outside, gt(cells, set1(k))));
      const __m256i wrap = eq(add(col, set1(1)), bw);
      for (int j = 0; j < 3; ++j) {
        const __m256i step = mul(dy[j], c256);  // -step_x
        const __m256i back = add(mul(step, col), mul(dx[j], c256));
        e[j] = add(e[j], select(wrap, back, sub(zero, step)));
      }
      col = select(wrap, zero, add(col, set1(1)));
    }
    // kSetUp 0, kCulled 1, kNoFragment 2.
    const __m256i no_fragment = _mm256_or_si256(empty, _mm256_andnot_si256(covers, small));
    const __m256i verdict = _mm256_and_si256(
        ok, select(culled, set1(1), _mm256_and_si256(no_fragment, set1(2))));
    alignas(32) std::int32_t v[8];
    _mm256_store_si256(reinterpret_cast<__m256i*>(v), verdict);
    for (int k = 0; k < 8; ++k) out[i + k] = std::uint8_t(v[k]);
  }
  triage_kernel_scalar(corners, i, n, params, out);  // the last n % 8
}

}  // namespace tessref::raster
