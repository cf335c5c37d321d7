#pragma once
// Every fixed-point format and rounding rule tessref uses, in one place, with the words of the
// specification (or the measured implementation choice) beside each.
#include <cmath>
#include <cstdint>
#include <cstring>

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

// ---------------------------------------------------------------------------------------------
// Framebuffer formats: what a fragment's float value becomes when an attachment of a fixed-point
// or 16-bit float format stores it. GL 4.6 section 17.3.9 (conversion to fixed-point: "c is
// clamped to [0, 1] and converted to unsigned normalized fixed point" by equation 2.3, which
// leaves the rounding to the implementation), 14.6.1 and 13.8.1 (depth values become fixed point
// the same way), 2.3.4.1 (the 16-bit float format; the rounding of a conversion is again the
// implementation's). tessref rounds as llvmpipe does, measured by rendering 262,144 values of
// each kind into each format with Mesa 22.3.6 and reading them back: 0 differences.

// An 8-bit unsigned normalized channel: clamp to [0, 1] (NaN to 0), then round c * 255 (in float)
// to the nearest integer, ties to even.
inline std::uint8_t unorm8_from_float(float c) {
  const float clamped = c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0f;  // NaN fails c > 0
  return static_cast<std::uint8_t>(std::nearbyint(clamped * 255.0f));
}
inline float unorm8_to_float(std::uint8_t k) { return float(k) / 255.0f; }
// The same for a b-bit channel (b <= 24, so the product is exact in double): the nearest of the
// 2^b steps, ties to even.
inline std::uint32_t unorm_from_float(float c, int bits) {
  const double clamped = c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0;
  return static_cast<std::uint32_t>(std::nearbyint(clamped * double((1u << bits) - 1u)));
}

// GL 4.6 section 17.3.6.1: with a fixed-point colour buffer, blending works on values in [0, 1];
// llvmpipe blends 8-bit channels in 8-bit arithmetic: a * b / 255 as (p + (p >> 8) + 128) >> 8
// with p = a * b, which is round(a * b / 255) but one step off where a * b / 255 lies within 1/255
// of a half (measured with GL_SRC_ALPHA / GL_ONE_MINUS_SRC_ALPHA over 262,144 channels: 0
// differences).
inline int unorm8_mul(int a, int b) {
  const int p = a * b;
  return (p + (p >> 8) + 128) >> 8;
}

// A 24-bit depth buffer: the window z in [0, 1] times 2^24 - 1, multiplied in float, rounded to
// the nearest integer, ties to even. Kept as the float nearest to k / (2^24 - 1): that map is
// increasing and one-to-one on 24-bit k, so comparing these floats compares the stored integers.
inline constexpr double kDepth24Max = 16777215.0;
inline std::uint32_t depth24_from_float(float z) {
  const float clamped = z > 0.0f ? (z < 1.0f ? z : 1.0f) : 0.0f;
  return static_cast<std::uint32_t>(std::nearbyint(clamped * float(kDepth24Max)));
}
inline float depth24_to_float(std::uint32_t k) { return float(double(k) / kDepth24Max); }
inline float quantize_depth24(float z) { return depth24_to_float(depth24_from_float(z)); }

// A 16-bit float channel (RGBA16F): llvmpipe converts float to half rounding toward zero; values
// beyond the largest half (65504) become it, infinities and NaN stay. Returned as the float of
// equal value.
inline float half_round_toward_zero(float f) {
  std::uint32_t bits;
  std::memcpy(&bits, &f, 4);
  const std::uint32_t sign = bits & 0x80000000u, magnitude = bits & 0x7fffffffu;
  if (magnitude >= 0x7f800000u) return f;  // infinity or NaN
  constexpr float kMaxHalf = 65504.0f;
  if (std::fabs(f) >= kMaxHalf) return sign ? -kMaxHalf : kMaxHalf;
  if (magnitude >= 0x38800000u) {  // |f| >= 2^-14: a normal half keeps 10 of the 23 mantissa bits
    const std::uint32_t kept = sign | (magnitude & ~0x1fffu);
    float out;
    std::memcpy(&out, &kept, 4);
    return out;
  }
  constexpr float kSubnormalStep = 5.9604644775390625e-8f;  // 2^-24, exact
  return std::trunc(f / kSubnormalStep) * kSubnormalStep;  // both steps exact
}

// ---------------------------------------------------------------------------------------------
// Textures. GL 4.6 section 8.14.2 gives the texel weights of GL_LINEAR as real numbers and leaves
// their precision open ("implementation-dependent"); 2.3.5.1 (equation 2.1) converts a normalized
// channel k to k / (2^b - 1), again at the implementation's precision. llvmpipe (Mesa 22.3.6;
// docs/textures.md, measured bit for bit) reads an 8-bit channel as k times the float nearest
// 1/255 (a multiply: 126 of the 256 values differ from k / 255.0f), and filters textures of 8-bit
// normalized channels in 8-bit fixed point: weights of 8 bits, each interpolation rounded.

inline float unorm8_texel_to_float(std::uint8_t k) { return float(k) * (1.0f / 255.0f); }
// Channels of up to 24 bits alike (lp_build_unsigned_norm_to_float: a b-bit value fits a float's
// 24-bit significand, so it is converted and multiplied by the float nearest 1 / (2^b - 1)).
inline float unorm_texel_to_float(std::uint32_t k, int bits) {
  return float(k) * static_cast<float>(1.0 / double((1u << bits) - 1u));
}

// v0 + (v1 - v0) * w / 256, rounded (ties up), for channels v0, v1 and a weight w in 0..255
// (lp_build_lerp with pre-scaled 8-bit weights).
inline std::uint8_t unorm8_lerp(int w, int v0, int v1) {
  return static_cast<std::uint8_t>((v0 + ((w * (v1 - v0) + 128) >> 8)) & 255);
}

}  // namespace tessref::fixed
