#pragma once
// Every fixed-point format and rounding rule tessref uses, in one place, with the words of the
// specification (or the measured implementation choice) beside each.
#include <cmath>
#include <cstdint>

namespace tessref::fixed {

// ---------------------------------------------------------------------------------------------
// Rasterizer: window coordinates snapped to a sub-pixel grid.
// GL 4.6 section 14.6.1 leaves the sub-pixel precision to the implementation
// (GL_SUBPIXEL_BITS, at least 4). tessref uses 8 bits, as llvmpipe does:
// window x, y are in 24.8 fixed point.
inline constexpr int kSubpixelBits = 8;
inline constexpr std::int32_t kSubpixelOne = 1 << kSubpixelBits;
// Largest window coordinate magnitude that keeps edge-function products in 64-bit:
// |x| < 2^(kGuardBits) pixels. Triangles are clipped at the viewport sides (raster/clip.cpp, as
// llvmpipe does), so window coordinates stay within [0, W] x [0, H] up to float rounding.
inline constexpr int kGuardBits = 14;

// Snap a window coordinate to 24.8 with round-to-nearest (ties to even), as llvmpipe's
// _mm_cvtps_epi32. Clipping keeps |window_coord| below 2^(kGuardBits + 1), so the result fits.
// Only the clipper's float rounding on absurd input (mesh coordinates near 1e37: fuzz_pipeline)
// leaves that range, or gives NaN; those clamp to its ends (NaN to the low one), since converting
// them would be undefined behaviour.
inline std::int32_t snap_subpixel(float window_coord) {
  constexpr float kLimit = float(1 << (kGuardBits + 1));
  const float c = std::fmin(std::fmax(window_coord, -kLimit), kLimit);
  return static_cast<std::int32_t>(std::nearbyint(c * float(kSubpixelOne)));
}
// Pixel (x, y) has its center at (x + 0.5, y + 0.5): in 24.8 that is x * 256 + 128.
inline constexpr std::int32_t kSubpixelHalf = kSubpixelOne / 2;
inline constexpr std::int64_t pixel_center(int pixel) {
  return std::int64_t(pixel) * kSubpixelOne + kSubpixelHalf;
}
// The viewport may be at most this wide or high: clipping at its sides keeps every snapped
// coordinate within 2^kGuardBits pixels (2^22 in 24.8), edge deltas below 2^23 and edge-function
// products below 2^47.
inline constexpr int kMaxViewportPixels = 1 << kGuardBits;
static_assert(2 * (kGuardBits + 1 + kSubpixelBits) + 2 < 63, "edge functions must fit in int64");

// Fill rule. GL 4.6 section 14.6.1 leaves it to the implementation: "if two polygons lie on
// either side of a common edge (with identical endpoints) on which a fragment center lies, then
// exactly one of the polygons results in the production of the fragment". tessref matches
// llvmpipe: top-left in framebuffer memory rows, i.e. bottom-left in GL window coordinates (y up;
// measured on Mesa 22.3.6 drawing into an FBO, tests/glref/raster_vs_llvmpipe_test.cpp). With the
// triangle wound counter-clockwise (interior to the left of each directed edge) an edge running
// (dx, dy) in 24.8 units is
//   "bottom": horizontal (dy == 0) with the interior above it, i.e. running toward +x (dx > 0);
//   "left":   interior to its right, i.e. running downward (dy < 0).
// A center exactly on a bottom or left edge is inside; on a top or right edge it is outside. The
// two triangles sharing an edge run it in opposite directions, so exactly one of them owns it.
inline constexpr bool is_top_left_edge(std::int64_t dx, std::int64_t dy) {
  return dy < 0 || (dy == 0 && dx > 0);
}

// ---------------------------------------------------------------------------------------------
// Tessellation primitive generator: unsigned 16.16 fixed point.
// GL 4.6 section 11.2.2: "the precision of the coordinates is implementation-dependent".
// llvmpipe (the D3D11 reference tessellator) subdivides in 16.16 fixed point, so every generated
// coordinate is a multiple of 2^-16 and 1 - x is exact (Appendix A.4 rule 8).
using Fx16 = std::uint32_t;
inline constexpr int kTessFractionBits = 16;
inline constexpr Fx16 kTessOne = 1u << kTessFractionBits;
inline constexpr Fx16 kTessHalf = kTessOne >> 1;
inline constexpr Fx16 kTessFractionMask = kTessOne - 1;
inline constexpr Fx16 kTessOneThird = 0x5555;   // floor(2^16 / 3)
inline constexpr Fx16 kTessTwoThirds = 0xAAAA;  // floor(2^17 / 3)

// Float level -> 16.16, round to nearest even (levels are already clamped to [1, 64]).
inline Fx16 tess_from_float(float level) {
  return static_cast<Fx16>(std::nearbyint(double(level) * double(kTessOne)));
}
// 16.16 -> float, exact for every value the generator produces (all are <= 1.0).
inline float tess_to_float(Fx16 v) { return float(double(v) / double(kTessOne)); }
inline Fx16 tess_floor(Fx16 v) { return v & ~kTessFractionMask; }
inline Fx16 tess_ceil(Fx16 v) { return (v & kTessFractionMask) ? tess_floor(v) + kTessOne : v; }
// Fixed-point product of two 16.16 values known to fit, rounded half up.
inline Fx16 tess_mul_round(Fx16 a, Fx16 b) { return (a * b + kTessHalf) >> kTessFractionBits; }

}  // namespace tessref::fixed
