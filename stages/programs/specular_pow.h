#pragma once
// pow(x, s) for the Phong programs' specular term, x = max(dot(r, view), 0) and s = the shininess
// (the scene allows 0 <= s <= inf). tessref's own code, not the C library's powf: libm's results
// change with its version and, through glibc's ifunc, with whether the CPU has FMA, and output
// bytes must not depend on which x86-64 machine ran tessref.
//
// Plain IEEE operations in double, no branches (the shading kernels run it over 64 lanes, and
// the AVX2 build vectorizes the loop), so PhongShader::shade and both kernel builds give the same
// bits (-ffp-contract=off everywhere). It is in an unnamed namespace on purpose: each includer,
// one of them compiled with -mavx2, keeps its own copy, and the linker cannot hand the AVX2 one to
// the plain build.
//
// x = 2^e * m with m in [sqrt(1/2), sqrt(2)); log2(m) = (2 / ln 2) * atanh(z), z = (m - 1) / (m + 1),
// |z| < 0.1716, by its odd series to z^17 (the first term left out is below 2^-50 of the sum);
// y = s * log2(x), clamped to [-160, 130] (beyond, the float result is 0 or inf either way);
// 2^y = 2^n * e^t with n = y rounded to the nearest integer and t = (y - n) * ln 2, |t| <= 0.347,
// by Taylor's series to t^12 (the first term left out is below 2^-52). The double result is
// within about 2^-43 of x^s relative, so the float is x^s correctly rounded unless x^s lies within
// 2^-19 ULP of halfway between two floats. Exact, as C99's powf: pow(x, 0) = pow(1, s) = 1 (a
// NaN x too), pow(0, s > 0) = 0, pow(inf, s > 0) = inf; another NaN x gives the NaN 0x7fc00000.
#include <cstdint>
#include <cstring>

namespace tessref::programs {
namespace {

inline float specular_pow(float x, float s) {
  std::uint32_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const bool subnormal = bits < 0x00800000u;             // +0 and the subnormals (x >= 0 here)
  const float scaled = subnormal ? x * 16777216.0f : x;  // times 2^24: exact
  std::memcpy(&bits, &scaled, sizeof bits);
  std::int32_t e = std::int32_t(bits >> 23) - (subnormal ? 127 + 24 : 127);
  std::uint32_t m_bits = (bits & 0x007fffffu) | 0x3f800000u;  // m in [1, 2)
  const bool halve = m_bits > 0x3fb504f3u;                    // m > sqrt(2)
  m_bits -= halve ? 0x00800000u : 0u;
  e += halve ? 1 : 0;
  float m_float;
  std::memcpy(&m_float, &m_bits, sizeof m_float);
  const double m = m_float;
  const double z = (m - 1.0) / (m + 1.0);
  const double z2 = z * z;
  // atanh(z) / z = sum of z^2k / (2k + 1), k = 0 .. 8, by Horner's rule from the highest term.
  constexpr double kAtanh[] = {1.0 / 15, 1.0 / 13, 1.0 / 11, 1.0 / 9, 1.0 / 7, 1.0 / 5, 1.0 / 3, 1.0};
  double p = 1.0 / 17;
  for (const double c : kAtanh) p = p * z2 + c;
  constexpr double kTwoOverLn2 = 2.8853900817779268;  // 2 / ln 2
  const double log2x = double(e) + (kTwoOverLn2 * z) * p;

  double y = double(s) * log2x;
  y = y < -160.0 ? -160.0 : y;
  y = y > 130.0 ? 130.0 : y;
  constexpr double kShifter = 0x1.8p52;  // y + 1.5 * 2^52: y rounded to an integer, in the low bits
  const double shifted = y + kShifter;
  const double n = shifted - kShifter;
  constexpr double kLn2 = 0.69314718055994529;
  const double t = (y - n) * kLn2;
  // e^t = sum of t^k / k!, k = 0 .. 12, by Horner's rule from the highest term.
  constexpr double kExp[] = {1.0 / 39916800, 1.0 / 3628800, 1.0 / 362880, 1.0 / 40320, 1.0 / 5040, 1.0 / 720,
                             1.0 / 120,      1.0 / 24,      1.0 / 6,      0.5,          1.0,        1.0};
  double q = 1.0 / 479001600;  // 1 / 12!
  for (const double c : kExp) q = q * t + c;
  // 2^n from the shifted value's low bits, 2^51 + n: (n + 1023) in the exponent field.
  std::uint64_t scale_bits;
  std::memcpy(&scale_bits, &shifted, sizeof scale_bits);
  scale_bits = (scale_bits + 1023u - (std::uint64_t(1) << 51)) << 52;
  double scale;
  std::memcpy(&scale, &scale_bits, sizeof scale);
  float result = float(q * scale);

  constexpr float kNaN = __builtin_nanf("");  // 0x7fc00000
  constexpr float kInf = __builtin_inff();
  result = x == 0.0f ? 0.0f : result;                    // pow(0, s > 0)
  result = x == kInf ? kInf : result;                    // pow(inf, s > 0)
  result = x != x ? kNaN : result;
  result = (s == 0.0f || x == 1.0f) ? 1.0f : result;     // pow(x, 0), pow(1, s): also for a NaN x
  return result;
}

}  // namespace
}  // namespace tessref::programs
