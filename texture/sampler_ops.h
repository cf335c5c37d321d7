#pragma once
// The scalar operations of llvmpipe's sampler code, with x86's semantics where they differ from
// C++'s: float-to-int conversions that give INT_MIN for NaN and values out of range (cvttps2dq,
// cvtps2dq), min and max that return their second operand when one is NaN (minps, maxps), 32-bit
// integer arithmetic that wraps, and interpolation as one fused multiply-add (llvm.fmuladd on a
// CPU with FMA; std::fma is exact on every machine, with or without the instruction).
#include <cmath>
#include <cstdint>
#include <limits>

namespace tessref::texture::ops {

using i32 = std::int32_t;

inline i32 add(i32 a, i32 b) { return i32(std::uint32_t(a) + std::uint32_t(b)); }

// Truncation (fptosi).
inline i32 fptosi(float x) {
  if (!(x > -2147483904.0f && x < 2147483648.0f)) return std::numeric_limits<i32>::min();
  return i32(x);
}
// Rounding to nearest, ties to even (lp_build_iround).
inline i32 iround(float x) { return fptosi(std::nearbyint(x)); }
inline i32 ifloor(float x) { return fptosi(std::floor(x)); }

inline float min_ps(float a, float b) { return a < b ? a : b; }
inline float max_ps(float a, float b) { return a > b ? a : b; }

// a + w * (b - a), fused (lp_build_lerp).
inline float lerp(float w, float a, float b) { return std::fma(w, b - a, a); }

}  // namespace tessref::texture::ops
