#pragma once
// IEEE 754 binary16 conversions, exact to the standard (no F16C instructions: the same bits on
// every x86-64 machine).
#include <bit>
#include <cmath>
#include <cstdint>

namespace tessref {

// IEEE half (binary16) from float, rounded to the nearest half, ties to even (GLSL packHalf2x16;
// texture formats with 16-bit float channels). Past the largest half: infinity; NaN stays NaN.
inline std::uint32_t half_from_float(float f) {
  const std::uint32_t x = std::bit_cast<std::uint32_t>(f);
  const std::uint32_t sign = (x >> 16) & 0x8000u;
  const std::uint32_t ax = x & 0x7fffffffu;
  if (ax > 0x7f800000u) return sign | 0x7e00u;  // NaN
  if (ax >= 0x477ff000u) return sign | 0x7c00u;  // overflow (incl. inf) after rounding
  if (ax < 0x38800000u) {                        // half subnormal or zero
    const float scaled = std::bit_cast<float>(ax) * 16777216.0f;  // 2^24: exact
    return sign | std::uint32_t(std::nearbyint(scaled));
  }
  const std::uint32_t mant = ax & 0x7fffffu;
  std::uint32_t h = ((ax >> 23) - 112u) << 10 | (mant >> 13);
  const std::uint32_t rest = mant & 0x1fffu;
  if (rest > 0x1000u || (rest == 0x1000u && (h & 1u))) ++h;
  return sign | h;
}
inline float half_to_float(std::uint32_t h) {
  const std::uint32_t sign = (h & 0x8000u) << 16;
  const std::uint32_t e = (h >> 10) & 0x1fu, m = h & 0x3ffu;
  if (e == 0) return std::bit_cast<float>(sign) + (sign ? -1.0f : 1.0f) * float(m) * (1.0f / 16777216.0f);
  if (e == 31) return std::bit_cast<float>(sign | 0x7f800000u | (m << 13));
  return std::bit_cast<float>(sign | ((e + 112u) << 23) | (m << 13));
}

}  // namespace tessref
