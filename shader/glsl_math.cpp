// GLSL's transcendental functions from tessref's own code (no libm), so that shader results are the
// same bits on every x86-64 machine. Each function works in double: an exact or nearly exact
// argument reduction, a truncated Taylor series whose first omitted term is below 2^-58 of the
// result, then one rounding to float. The double value lies within 2^-45 (relative) of the exact
// one, a few double ULPs for all but pow, so the float is the correctly rounded result except when
// the exact value is that close to halfway between two floats. Only +, -, *, /, sqrt and integer operations are used, all exactly specified
// by IEEE 754 under the project's -ffp-contract=off -fno-fast-math.
#include "shader/glsl_math.h"

#include <array>
#include <bit>
#include <cfloat>
#include <cmath>  // std::sqrt only: correctly rounded, hence the same everywhere
#include <cstdint>

namespace tessref::shader::math {
namespace {

static_assert(FLT_EVAL_METHOD == 0, "float and double expressions must be evaluated in their type");

// Every NaN result has these bits, whatever NaN came in: payload propagation would depend on the
// order in which a compiler puts the operands of an addition.
constexpr float kNaN = std::bit_cast<float>(0x7fc00000u);
constexpr float kInf = std::bit_cast<float>(0x7f800000u);

constexpr double kPi = 0x1.921fb54442d18p+1;
constexpr double kHalfPi = 0x1.921fb54442d18p+0;
constexpr double kLn2 = 0x1.62e42fefa39efp-1;
// ln 2 split so that k * kLn2Hi is exact for |k| < 2^11: kLn2Hi holds its first 42 bits.
constexpr double kLn2Hi = 0x1.62e42fefa38p-1;
constexpr double kLn2Lo = 0x1.ef35793c7673p-45;
constexpr double kLog2e = 0x1.71547652b82fep+0;  // 1 / ln 2
constexpr double kSqrt2 = 0x1.6a09e667f3bcdp+0;

bool is_nan(float x) { return x != x; }
bool is_finite(float x) { return (std::bit_cast<uint32_t>(x) & 0x7f800000u) != 0x7f800000u; }
bool sign_bit(float x) { return std::bit_cast<uint32_t>(x) >> 31; }
float abs(float x) { return std::bit_cast<float>(std::bit_cast<uint32_t>(x) & 0x7fffffffu); }
// Applies the sign of odd functions: f(-x) = -f(x), including f(-0) = -0.
float with_sign_of(float x, float v) { return sign_bit(x) ? -v : v; }

// 2^k, for -1022 <= k <= 1023.
double pow2i(int k) { return std::bit_cast<double>(uint64_t(k + 1023) << 52); }
// Nearest integer, halves away from zero; |x| < 2^31. Callers tolerate a neighbour in the rare
// case where the addition rounds, since their reduced argument stays well inside the series' range.
int round_to_int(double x) { return int(x < 0 ? x - 0.5 : x + 0.5); }

constexpr double inv_factorial(int n) {
  double f = 1;  // n! is exact in double for n <= 22
  for (int i = 2; i <= n; ++i) f *= i;
  return 1 / f;
}

// A polynomial's coefficients term(0), term(1), ..., stored highest degree first for horner().
template <int N, class Term>
constexpr std::array<double, N> coefficients(Term term) {
  std::array<double, N> c{};
  for (int k = 0; k < N; ++k) c[N - 1 - k] = term(k);
  return c;
}

template <std::size_t N>
double horner(const std::array<double, N>& c, double x) {
  double p = c[0];
  for (std::size_t i = 1; i < N; ++i) p = p * x + c[i];
  return p;
}

// Taylor series; each comment gives the bound on the argument and, there, the first omitted term
// relative to the sum.
// sin r = r * sum (-1)^k r^2k / (2k+1)!, |r| <= pi/4: r^18/19! < 2^-62.
constexpr auto kSin =
    coefficients<9>([](int k) { return (k % 2 ? -1 : 1) * inv_factorial(2 * k + 1); });
// cos r = sum (-1)^k r^2k / (2k)!, |r| <= pi/4: r^18/18! < 2^-58.
constexpr auto kCos =
    coefficients<9>([](int k) { return (k % 2 ? -1 : 1) * inv_factorial(2 * k); });
// e^r - 1 = r * sum r^k / (k+1)!, |r| <= ln2/2 (+ a little): r^14/15! < 2^-61.
constexpr auto kExpm1 = coefficients<14>([](int k) { return inv_factorial(k + 1); });
// atan u = u * sum (-1)^k u^2k / (2k+1), |u| <= 1/16: u^14/15 < 2^-59.
constexpr auto kAtan = coefficients<7>([](int k) { return (k % 2 ? -1.0 : 1.0) / (2 * k + 1); });
// ln((1+s)/(1-s)) = 2s * sum s^2k / (2k+1), |s| <= 3 - 2 sqrt 2 = 0.172: s^22/23 < 2^-60.
constexpr auto kLog = coefficients<11>([](int k) { return 1.0 / (2 * k + 1); });

// atan(i/8), i = 0..8, rounded to double (computed with 600-bit arithmetic).
constexpr double kAtanEighths[9] = {
    0.0,
    0.12435499454676144,
    0.24497866312686414,
    0.35877067027057225,
    0.46364760900080609,
    0.55859931534356244,
    0.64350110879328437,
    0.71882999962162453,
    0.78539816339744828,
};

// The bits of 2/pi after the binary point, 64 to a word, behind a zero word that lets a window
// start up to 63 bits before the point.
constexpr uint64_t kTwoOverPi[5] = {0, 0xa2f9836e4e441529, 0xfc2757d1f534ddc0,
                                    0xdb6295993c439041, 0xfe5163abdebbc561};

double sin_kernel(double r) { return r * horner(kSin, r * r); }  // keeps the sign of r = +-0
double cos_kernel(double r) { return horner(kCos, r * r); }

struct Reduced {
  double r;           // |r| <= pi/4 (plus a rounding)
  unsigned quadrant;  // 0..3
};

// ax = (n + f) * pi/2 with an integer n, |f| <= 1/2, for finite ax >= 0: returns r = f * pi/2 and
// n mod 4. ax = m * 2^e exactly, with m an integer below 2^24, so ax * 2/pi mod 4 needs the bits of
// 2/pi only from 2^(1-e) on: earlier bits add multiples of 4. A 128-bit window of them gives the
// fraction to within 2^-102 of a quadrant. No float lies closer than 2^-30 quadrant to a multiple
// of pi/2 (the nearest, 0x1.f37c8ap+95, 2^-29.9; found by trying all), so over 70 bits of f are
// right.
Reduced reduce_quadrant(float ax) {
  if (ax <= kPi / 4) return {ax, 0};
  const uint32_t bits = std::bit_cast<uint32_t>(ax);
  const int e = int(bits >> 23) - 150;  // >= -24 above pi/4, <= 104
  const uint64_t m = (bits & 0x7fffffu) | 0x800000u;
  // Window: bits 2^(1-e) .. 2^(-126-e) of 2/pi as a 128-bit integer (table bit index e + 62).
  using u128 = unsigned __int128;
  const int word = (e + 62) / 64, shift = (e + 62) % 64;
  const u128 first = (u128(kTwoOverPi[word]) << 64) | kTwoOverPi[word + 1];
  const u128 window = (first << shift) | ((kTwoOverPi[word + 2] >> 1) >> (63 - shift));
  // ax * 2/pi = m * window * 2^-126 (mod 4): the top 2 bits are n, the other 126 the fraction.
  const u128 product = m * window;
  unsigned quadrant = unsigned(product >> 126);
  u128 fraction = product << 2;  // scaled by 2^128
  const bool round_up = fraction >> 127;
  if (round_up) {  // f >= 1/2: the next quadrant, with f - 1 < 0
    ++quadrant;
    fraction = -fraction;
  }
  const double f =
      double(uint64_t(fraction >> 64)) * 0x1p-64 + double(uint64_t(fraction)) * 0x1p-128;
  return {(round_up ? -f : f) * kHalfPi, quadrant & 3};
}

// atan t for t >= 0, t may be +inf.
double atan_pos(double t) {
  const bool inverted = t > 1;  // atan t = pi/2 - atan(1/t)
  if (inverted) t = 1 / t;
  // atan t = atan c + atan u with c = i/8 nearest t and u = (t - c) / (1 + t c), |u| <= 1/16;
  // t - c is exact (Sterbenz).
  const int i = int(t * 8 + 0.5);
  const double c = i * 0.125;
  const double u = (t - c) / (1 + t * c);
  const double a = kAtanEighths[i] + u * horner(kAtan, u * u);
  return inverted ? kHalfPi - a : a;
}

double expm1_small(double r) { return r * horner(kExpm1, r); }  // |r| <= ~ln2/2

// e^x for |x| < 700: x = k ln2 + r, |r| <= ln2/2; k * kLn2Hi and x - k * kLn2Hi are exact for
// float x.
double exp_d(double x) {
  const int k = round_to_int(x * kLog2e);
  const double r = (x - k * kLn2Hi) - k * kLn2Lo;
  return (1 + expm1_small(r)) * pow2i(k);
}

// e^x - 1 for |x| < 700, with a small relative error also near 0.
double expm1_d(double x) {
  return (x < -kLn2 / 2 || x > kLn2 / 2) ? exp_d(x) - 1 : expm1_small(x);
}

// 2^t for |t| < 1000: t = k + f with |f| <= 1/2, f exact.
double exp2_d(double t) {
  const int k = round_to_int(t);
  return (1 + expm1_small((t - k) * kLn2)) * pow2i(k);
}

// x = m * 2^e with m in [sqrt(1/2), sqrt(2)), for finite normal x > 0.
struct Split {
  int e;
  double m;
};
Split split_exponent(double x) {
  const uint64_t bits = std::bit_cast<uint64_t>(x);
  Split s{int(bits >> 52) - 1023,
          std::bit_cast<double>((bits & 0x000fffffffffffffu) | 0x3ff0000000000000u)};
  if (s.m > kSqrt2) {
    s.m *= 0.5;
    ++s.e;
  }
  return s;
}

// ln m = ln((1+s)/(1-s)) with s = (m-1)/(m+1), |s| <= 0.172; m - 1 is exact.
double log_mantissa(double m) {
  const double s = (m - 1) / (m + 1);
  return 2 * s * horner(kLog, s * s);
}

// ln x and log2 x for finite normal x > 0; exactly 0 at x = 1 and exactly e at x = 2^e.
double log_d(double x) {
  const Split s = split_exponent(x);
  return s.e * kLn2 + log_mantissa(s.m);
}
double log2_d(double x) {
  const Split s = split_exponent(x);
  return s.e + log_mantissa(s.m) * kLog2e;
}

// ln(1 + u) for finite u >= 0, with a small relative error also near 0.
double log1p_d(double u) {
  if (u < kSqrt2 - 1) {
    const double s = u / (2 + u);  // 1 + u = (1+s)/(1-s), without rounding 1 + u
    return 2 * s * horner(kLog, s * s);
  }
  return log_d(1 + u);
}

// For pow: 0 when y is not an integer, 1 when it is an odd one, 2 when an even one (or +-inf).
int integer_kind(float y) {
  const uint32_t bits = std::bit_cast<uint32_t>(y) & 0x7fffffffu;
  const int e = int(bits >> 23) - 127;
  if (e < 0) return bits == 0 ? 2 : 0;  // |y| < 1
  if (e > 23) return 2;                 // |y| >= 2^24: all even
  const uint32_t m = (bits & 0x7fffffu) | 0x800000u;
  const int shift = 23 - e;             // bits below the units bit
  if (m & ((1u << shift) - 1)) return 0;
  return (m >> shift) & 1 ? 1 : 2;
}

}  // namespace

float sin(float x) {
  if (!is_finite(x)) return kNaN;
  const Reduced a = reduce_quadrant(abs(x));
  const double s = (a.quadrant & 1) ? cos_kernel(a.r) : sin_kernel(a.r);
  return with_sign_of(x, float(a.quadrant & 2 ? -s : s));
}

float cos(float x) {
  if (!is_finite(x)) return kNaN;
  const Reduced a = reduce_quadrant(abs(x));
  const double c = (a.quadrant & 1) ? sin_kernel(a.r) : cos_kernel(a.r);
  return float((a.quadrant + 1) & 2 ? -c : c);  // negative in quadrants 1 and 2
}

float tan(float x) {
  if (!is_finite(x)) return kNaN;
  const Reduced a = reduce_quadrant(abs(x));
  const double s = sin_kernel(a.r), c = cos_kernel(a.r);
  return with_sign_of(x, float(a.quadrant & 1 ? -c / s : s / c));  // s != 0 when odd: r != 0
}

float asin(float x) {
  if (!(abs(x) <= 1)) return kNaN;
  const double d = abs(x);
  // asin x = atan(x / sqrt(1 - x^2)); (1 - x)(1 + x) has exact factors. At |x| = 1: atan(inf).
  return with_sign_of(x, float(atan_pos(d / std::sqrt((1 - d) * (1 + d)))));
}

float acos(float x) {
  if (!(abs(x) <= 1)) return kNaN;
  const double d = x, ad = abs(x);
  const double a = atan_pos(std::sqrt((1 - d) * (1 + d)) / ad);  // x = +-0: atan(inf) = pi/2
  return float(x < 0 ? kPi - a : a);
}

float atan(float x) {
  if (is_nan(x)) return kNaN;
  return with_sign_of(x, float(atan_pos(abs(x))));
}

float atan2(float y, float x) {
  if (is_nan(x) || is_nan(y)) return kNaN;
  const double ax = abs(x), ay = abs(y);
  // The ratio fits double's range for any floats. C99's atan2(+-0, +-0) and atan2(+-inf, +-inf)
  // take it as 0 and 1.
  const double t = ay == ax ? (ax == 0 ? 0.0 : 1.0) : ay / ax;
  const double a = atan_pos(t);
  return with_sign_of(y, float(sign_bit(x) ? kPi - a : a));
}

float sinh(float x) {
  if (is_nan(x)) return kNaN;
  const float ax = abs(x);
  if (ax > 90) return with_sign_of(x, kInf);  // overflows from 89.42; keeps exp_d in range
  // (e^x - e^-x)/2 = (E + E/(E+1))/2 with E = e^x - 1: no cancellation near 0.
  const double em = expm1_d(ax);
  return with_sign_of(x, float(0.5 * (em + em / (em + 1))));
}

float cosh(float x) {
  if (is_nan(x)) return kNaN;
  const float ax = abs(x);
  if (ax > 90) return kInf;
  const double e = exp_d(ax);
  return float(0.5 * (e + 1 / e));
}

float tanh(float x) {
  if (is_nan(x)) return kNaN;
  const float ax = abs(x);
  if (ax > 10) return with_sign_of(x, 1.0f);  // 1 - tanh x < 2^-25 from 9.02 on
  // (e^2x - 1) / (e^2x + 1) with E = e^2x - 1.
  const double em = expm1_d(2.0 * ax);
  return with_sign_of(x, float(em / (em + 2)));
}

float asinh(float x) {
  if (is_nan(x)) return kNaN;
  const float ax = abs(x);
  if (ax == kInf) return x;
  // ln(x + sqrt(x^2 + 1)) = ln(1 + u), u = x + x^2 / (1 + sqrt(x^2 + 1)); x^2 fits double.
  const double d = ax, d2 = d * d;
  return with_sign_of(x, float(log1p_d(d + d2 / (1 + std::sqrt(1 + d2)))));
}

float acosh(float x) {
  if (!(x >= 1)) return kNaN;  // also NaN and -inf
  if (x == kInf) return kInf;
  // ln(x + sqrt(x^2 - 1)) = ln(1 + t + sqrt(t (t + 2))), t = x - 1 exact: accurate near 1.
  const double t = double(x) - 1;
  return float(log1p_d(t + std::sqrt(t * (t + 2))));
}

float atanh(float x) {
  const float ax = abs(x);
  if (!(ax <= 1)) return kNaN;
  if (ax == 1) return with_sign_of(x, kInf);
  // ln((1+x)/(1-x)) / 2 = ln(1 + 2x/(1-x)) / 2; 1 - x is exact.
  const double d = ax;
  return with_sign_of(x, float(0.5 * log1p_d(2 * d / (1 - d))));
}

float exp(float x) {
  if (is_nan(x)) return kNaN;
  if (x > 89) return kInf;  // e^88.73 > FLT_MAX; also +inf
  if (x < -104) return 0;   // e^-104 < 2^-150 rounds to 0; also -inf
  return float(exp_d(x));
}

float exp2(float x) {
  if (is_nan(x)) return kNaN;
  if (x >= 128) return kInf;
  if (x < -151) return 0;
  return float(exp2_d(x));
}

float log(float x) {
  if (is_nan(x) || x < 0) return kNaN;
  if (x == 0) return -kInf;
  if (x == kInf) return kInf;
  return float(log_d(x));
}

float log2(float x) {
  if (is_nan(x) || x < 0) return kNaN;
  if (x == 0) return -kInf;
  if (x == kInf) return kInf;
  return float(log2_d(x));
}

// C99's powf, case by case (Annex F.9.4.4).
float pow(float x, float y) {
  if (y == 0 || x == 1) return 1;  // even when the other one is NaN
  if (is_nan(x) || is_nan(y)) return kNaN;
  const float ax = abs(x);
  const int kind = integer_kind(y);
  const bool negative = sign_bit(x) && kind == 1;  // x < 0 (or -0, -inf), y an odd integer
  if (!is_finite(y)) {
    if (ax == 1) return 1;  // (-1)^+-inf
    return (ax < 1) == (y < 0) ? kInf : 0.0f;
  }
  if (ax == 0 || ax == kInf) {  // 0^y < 0 and inf^y > 0 are infinite, the other two zero
    const float v = (ax == 0) == (y < 0) ? kInf : 0.0f;
    return negative ? -v : v;
  }
  if (x < 0 && kind == 0) return kNaN;
  // |x|^y = 2^t. Beyond the bounds the result over- or underflows; within them exp2_d's scale fits.
  const double t = y * log2_d(ax);
  const float v = t >= 129 ? kInf : t <= -152 ? 0.0f : float(exp2_d(t));
  return negative ? -v : v;
}

namespace {

template <float (*F)(float)>
void apply(const float* x, float* out, int n) {
  for (int i = 0; i < n; ++i) out[i] = F(x[i]);
}

template <float (*F)(float, float)>
void apply(const float* a, const float* b, float* out, int n) {
  for (int i = 0; i < n; ++i) out[i] = F(a[i], b[i]);
}

}  // namespace

void sin_n(const float* x, float* out, int n) { apply<sin>(x, out, n); }
void cos_n(const float* x, float* out, int n) { apply<cos>(x, out, n); }
void tan_n(const float* x, float* out, int n) { apply<tan>(x, out, n); }
void asin_n(const float* x, float* out, int n) { apply<asin>(x, out, n); }
void acos_n(const float* x, float* out, int n) { apply<acos>(x, out, n); }
void atan_n(const float* x, float* out, int n) { apply<atan>(x, out, n); }
void sinh_n(const float* x, float* out, int n) { apply<sinh>(x, out, n); }
void cosh_n(const float* x, float* out, int n) { apply<cosh>(x, out, n); }
void tanh_n(const float* x, float* out, int n) { apply<tanh>(x, out, n); }
void asinh_n(const float* x, float* out, int n) { apply<asinh>(x, out, n); }
void acosh_n(const float* x, float* out, int n) { apply<acosh>(x, out, n); }
void atanh_n(const float* x, float* out, int n) { apply<atanh>(x, out, n); }
void exp_n(const float* x, float* out, int n) { apply<exp>(x, out, n); }
void exp2_n(const float* x, float* out, int n) { apply<exp2>(x, out, n); }
void log_n(const float* x, float* out, int n) { apply<log>(x, out, n); }
void log2_n(const float* x, float* out, int n) { apply<log2>(x, out, n); }
void pow_n(const float* x, const float* y, float* out, int n) { apply<pow>(x, y, out, n); }
void atan2_n(const float* y, const float* x, float* out, int n) { apply<atan2>(y, x, out, n); }

}  // namespace tessref::shader::math
