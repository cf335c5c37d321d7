// tessref::shader::math: the largest error in ULPs over dense samples against libm's double
// functions (used here as the reference only; the library itself uses no libm), C99 Annex F's
// special values bit for bit, the array variants against the scalar ones, and a hash of the output
// bits on fixed inputs that pins the results across machines and compilers.
#include "shader/glsl_math.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <vector>

namespace {

namespace m = tessref::shader::math;

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::bit_cast<float>(0x7fc00000u);  // the library's only NaN

// Error of got against the exact value ref (a double), in ULPs of float at ref. A result that
// over- or underflows must be what ref rounds to.
double ulp_error(float got, double ref) {
  if (std::isnan(ref)) return std::isnan(got) ? 0 : INFINITY;
  const float rounded = float(ref);
  if (std::isinf(got) || std::isinf(rounded)) return got == rounded ? 0 : INFINITY;
  const int e = std::max(std::ilogb(ref), -126);  // ilogb(0) is very negative
  return std::fabs(double(got) - ref) / std::ldexp(1.0, e - 23);
}

// Floats ordered as integers: a < b iff key(a) < key(b). Stepping through keys visits every
// magnitude, from denormals up, evenly.
int64_t key(float f) {
  const uint32_t b = std::bit_cast<uint32_t>(f);
  return b >> 31 ? -int64_t(b & 0x7fffffffu) : int64_t(b);
}
float from_key(int64_t k) {
  return std::bit_cast<float>(k < 0 ? uint32_t(-k) | 0x80000000u : uint32_t(k));
}

// n samples of [lo, hi]: half evenly spaced in key (all magnitudes), half evenly in value.
std::vector<float> samples(float lo, float hi, int n) {
  std::vector<float> v;
  const int64_t klo = key(lo), khi = key(hi);
  for (int i = 0; i < n / 2; ++i) v.push_back(from_key(klo + (khi - klo) * i / (n / 2 - 1)));
  for (int i = 0; i < n / 2; ++i) v.push_back(float(lo + (double(hi) - lo) * (i + 0.5) / (n / 2)));
  return v;
}

// The largest error seen, where, and how many results were not ref rounded to float.
struct Worst {
  double ulp = 0;
  float x = 0, y = 0;
  std::size_t count = 0, misrounded = 0;
};

void record(Worst& w, float got, double ref, float x, float y = 0) {
  const double err = ulp_error(got, ref);
  if (err > w.ulp) {
    w.ulp = err;
    w.x = x;
    w.y = y;
  }
  ++w.count;
  if (std::bit_cast<uint32_t>(got) != std::bit_cast<uint32_t>(float(ref)) && !std::isnan(ref))
    ++w.misrounded;
}

void report(const char* name, const Worst& w, double bound, bool binary = false) {
  std::printf("  %-6s max %.9f ULP at x=%a", name, w.ulp, w.x);
  if (binary) std::printf(" y=%a", w.y);
  std::printf("; %zu of %zu samples not correctly rounded\n", w.misrounded, w.count);
  EXPECT_LE(w.ulp, bound) << name << " at x=" << w.x << " y=" << w.y;
}

using Unary = float (*)(float);
using Ref = double (*)(double);

void check_unary(const char* name, Unary f, Ref ref, const std::vector<float>& xs, double bound) {
  Worst w;
  for (const float x : xs) record(w, f(x), ref(x), x);
  report(name, w, bound);
}

std::vector<float> join(std::vector<float> a, const std::vector<float>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

constexpr int kDense = 1'000'000;
// Correctly rounded, but for rare cases within ~2^-21 ULP of halfway between two floats, and the
// reference's own error.
constexpr double kBound = 0.50001;

// sin, cos, tan: densely up to 1e5, then sparser up to FLT_MAX (every binade), and the float that
// lies nearest a multiple of pi/2 (the worst case of the argument reduction).
std::vector<float> trig_samples() {
  std::vector<float> v = join(samples(-1e5f, 1e5f, kDense), samples(1e5f, FLT_MAX, 200'000));
  v.push_back(0x1.f37c8ap+95f);
  return v;
}

TEST(GlslMathAccuracy, Sin) {
  check_unary("sin", m::sin, [](double x) { return std::sin(x); }, trig_samples(), kBound);
}
TEST(GlslMathAccuracy, Cos) {
  check_unary("cos", m::cos, [](double x) { return std::cos(x); }, trig_samples(), kBound);
}
TEST(GlslMathAccuracy, Tan) {
  check_unary("tan", m::tan, [](double x) { return std::tan(x); }, trig_samples(), kBound);
}
TEST(GlslMathAccuracy, Asin) {
  check_unary("asin", m::asin, [](double x) { return std::asin(x); }, samples(-1, 1, kDense),
              kBound);
}
TEST(GlslMathAccuracy, Acos) {
  check_unary("acos", m::acos, [](double x) { return std::acos(x); }, samples(-1, 1, kDense),
              kBound);
}
TEST(GlslMathAccuracy, Atan) {
  check_unary("atan", m::atan, [](double x) { return std::atan(x); },
              join(samples(-FLT_MAX, FLT_MAX, kDense), samples(-10, 10, kDense / 2)), kBound);
}
TEST(GlslMathAccuracy, Sinh) {
  check_unary("sinh", m::sinh, [](double x) { return std::sinh(x); }, samples(-90, 90, kDense),
              kBound);
}
TEST(GlslMathAccuracy, Cosh) {
  check_unary("cosh", m::cosh, [](double x) { return std::cosh(x); }, samples(-90, 90, kDense),
              kBound);
}
TEST(GlslMathAccuracy, Tanh) {
  check_unary("tanh", m::tanh, [](double x) { return std::tanh(x); },
              join(samples(-10, 10, kDense), samples(-FLT_MAX, FLT_MAX, kDense / 4)), kBound);
}
TEST(GlslMathAccuracy, Asinh) {
  check_unary("asinh", m::asinh, [](double x) { return std::asinh(x); },
              join(samples(-FLT_MAX, FLT_MAX, kDense), samples(-10, 10, kDense / 2)), kBound);
}
TEST(GlslMathAccuracy, Acosh) {
  check_unary("acosh", m::acosh, [](double x) { return std::acosh(x); },
              join(samples(1, FLT_MAX, kDense), samples(1, 10, kDense / 2)), kBound);
}
TEST(GlslMathAccuracy, Atanh) {
  check_unary("atanh", m::atanh, [](double x) { return std::atanh(x); }, samples(-1, 1, kDense),
              kBound);
}
TEST(GlslMathAccuracy, Exp) {
  check_unary("exp", m::exp, [](double x) { return std::exp(x); }, samples(-104, 89, kDense),
              kBound);
}
TEST(GlslMathAccuracy, Exp2) {
  check_unary("exp2", m::exp2, [](double x) { return std::exp2(x); }, samples(-151, 128, kDense),
              kBound);
}
// All positive floats, denormals included, and densely GLSL's absolute-error range [0.5, 2].
TEST(GlslMathAccuracy, Log) {
  check_unary("log", m::log, [](double x) { return std::log(x); },
              join(samples(FLT_TRUE_MIN, FLT_MAX, kDense), samples(0.5f, 2, kDense / 2)), kBound);
}
TEST(GlslMathAccuracy, Log2) {
  check_unary("log2", m::log2, [](double x) { return std::log2(x); },
              join(samples(FLT_TRUE_MIN, FLT_MAX, kDense), samples(0.5f, 2, kDense / 2)), kBound);
}

// x over all positive floats with y chosen so that x^y spans the float range; x in [0, 4] with
// y in [-30, 30]; negative x with integer y.
TEST(GlslMathAccuracy, Pow) {
  Worst w;
  auto check = [&](float x, float y) {
    record(w, m::pow(x, y), std::pow(double(x), double(y)), x, y);
  };
  const std::vector<float> xs = samples(FLT_TRUE_MIN, FLT_MAX, kDense / 2);
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const double t = -150 + 278.0 * ((i * 7919) % xs.size()) / xs.size();  // log2 of the result
    if (xs[i] != 1) check(xs[i], float(t / std::log2(double(xs[i]))));
  }
  const std::vector<float> ys = samples(-30, 30, kDense / 4);
  const std::vector<float> bases = samples(0, 4, kDense / 4);
  for (std::size_t i = 0; i < ys.size(); ++i) check(bases[(i * 7919) % bases.size()], ys[i]);
  for (int i = 0; i < kDense / 4; ++i) check(-10 + 10.0f * i / (kDense / 4), float(i % 81 - 40));
  report("pow", w, kBound, true);
}

// y and x over all finite floats, and densely over [-1, 1]^2.
TEST(GlslMathAccuracy, Atan2) {
  Worst w;
  auto check = [&](const std::vector<float>& ys, const std::vector<float>& xs) {
    for (std::size_t i = 0; i < ys.size(); ++i) {
      const float y = ys[i], x = xs[(i * 7919) % xs.size()];
      record(w, m::atan2(y, x), std::atan2(double(y), double(x)), x, y);
    }
  };
  const std::vector<float> all = samples(-FLT_MAX, FLT_MAX, kDense / 2);
  const std::vector<float> unit = samples(-1, 1, kDense / 2);
  check(all, all);
  check(unit, unit);
  report("atan2", w, kBound, true);
}

// Special values, bit for bit (so signed zeros count and NaN is the library's).
constexpr float kPi = 3.14159265358979f, kHalfPi = kPi / 2, kQuarterPi = kPi / 4;

#define EXPECT_BITS(expr, want) \
  EXPECT_EQ(std::bit_cast<uint32_t>(float(expr)), std::bit_cast<uint32_t>(float(want))) << #expr

TEST(GlslMathSpecial, Trigonometric) {
  const float nan_in = std::bit_cast<float>(0xffc01234u);  // another NaN: comes out canonical
  for (const Unary f : {m::sin, m::cos, m::tan}) {
    EXPECT_BITS(f(kInf), kNaN);
    EXPECT_BITS(f(-kInf), kNaN);
    EXPECT_BITS(f(nan_in), kNaN);
  }
  EXPECT_BITS(m::sin(0.0f), 0.0f);
  EXPECT_BITS(m::sin(-0.0f), -0.0f);
  EXPECT_BITS(m::sin(-FLT_TRUE_MIN), -FLT_TRUE_MIN);
  EXPECT_BITS(m::cos(0.0f), 1.0f);
  EXPECT_BITS(m::cos(-0.0f), 1.0f);
  EXPECT_BITS(m::tan(0.0f), 0.0f);
  EXPECT_BITS(m::tan(-0.0f), -0.0f);

  EXPECT_BITS(m::asin(0.0f), 0.0f);
  EXPECT_BITS(m::asin(-0.0f), -0.0f);
  EXPECT_BITS(m::asin(1.0f), kHalfPi);
  EXPECT_BITS(m::asin(-1.0f), -kHalfPi);
  EXPECT_BITS(m::asin(1.0000001f), kNaN);
  EXPECT_BITS(m::asin(-kInf), kNaN);
  EXPECT_BITS(m::acos(1.0f), 0.0f);
  EXPECT_BITS(m::acos(-1.0f), kPi);
  EXPECT_BITS(m::acos(0.0f), kHalfPi);
  EXPECT_BITS(m::acos(-0.0f), kHalfPi);
  EXPECT_BITS(m::acos(-1.0000001f), kNaN);
  EXPECT_BITS(m::acos(nan_in), kNaN);
  EXPECT_BITS(m::atan(0.0f), 0.0f);
  EXPECT_BITS(m::atan(-0.0f), -0.0f);
  EXPECT_BITS(m::atan(kInf), kHalfPi);
  EXPECT_BITS(m::atan(-kInf), -kHalfPi);
  EXPECT_BITS(m::atan(nan_in), kNaN);
}

TEST(GlslMathSpecial, Atan2Quadrants) {
  for (const float s : {1.0f, -1.0f}) {  // the result takes y's sign
    EXPECT_BITS(m::atan2(s * 0.0f, 0.0f), s * 0.0f);
    EXPECT_BITS(m::atan2(s * 0.0f, -0.0f), s * kPi);
    EXPECT_BITS(m::atan2(s * 0.0f, 2.0f), s * 0.0f);
    EXPECT_BITS(m::atan2(s * 0.0f, -2.0f), s * kPi);
    EXPECT_BITS(m::atan2(s * 2.0f, 0.0f), s * kHalfPi);
    EXPECT_BITS(m::atan2(s * 2.0f, -0.0f), s * kHalfPi);
    EXPECT_BITS(m::atan2(s * 2.0f, kInf), s * 0.0f);
    EXPECT_BITS(m::atan2(s * 2.0f, -kInf), s * kPi);
    EXPECT_BITS(m::atan2(s * kInf, 2.0f), s * kHalfPi);
    EXPECT_BITS(m::atan2(s * kInf, -2.0f), s * kHalfPi);
    EXPECT_BITS(m::atan2(s * kInf, kInf), s * kQuarterPi);
    EXPECT_BITS(m::atan2(s * kInf, -kInf), s * 2.3561945f);  // 3pi/4
    EXPECT_BITS(m::atan2(s * 1.0f, 1.0f), s * kQuarterPi);
    EXPECT_BITS(m::atan2(s * kNaN, 1.0f), kNaN);
    EXPECT_BITS(m::atan2(1.0f, s * kNaN), kNaN);
  }
}

TEST(GlslMathSpecial, Hyperbolic) {
  for (const Unary f : {m::sinh, m::tanh, m::asinh, m::atanh}) {  // odd, and exact at 0
    EXPECT_BITS(f(0.0f), 0.0f);
    EXPECT_BITS(f(-0.0f), -0.0f);
  }
  for (const Unary f : {m::sinh, m::cosh, m::tanh, m::asinh, m::acosh, m::atanh})
    EXPECT_BITS(f(kNaN), kNaN);
  EXPECT_BITS(m::sinh(kInf), kInf);
  EXPECT_BITS(m::sinh(-kInf), -kInf);
  EXPECT_BITS(m::sinh(89.5f), kInf);
  EXPECT_BITS(m::sinh(-1e30f), -kInf);
  EXPECT_BITS(m::cosh(0.0f), 1.0f);
  EXPECT_BITS(m::cosh(-0.0f), 1.0f);
  EXPECT_BITS(m::cosh(-kInf), kInf);
  EXPECT_BITS(m::cosh(89.5f), kInf);
  EXPECT_BITS(m::tanh(kInf), 1.0f);
  EXPECT_BITS(m::tanh(-kInf), -1.0f);
  EXPECT_BITS(m::tanh(-20.0f), -1.0f);
  EXPECT_BITS(m::asinh(kInf), kInf);
  EXPECT_BITS(m::asinh(-kInf), -kInf);
  EXPECT_BITS(m::acosh(1.0f), 0.0f);
  EXPECT_BITS(m::acosh(kInf), kInf);
  EXPECT_BITS(m::acosh(0.99999994f), kNaN);
  EXPECT_BITS(m::acosh(-kInf), kNaN);
  EXPECT_BITS(m::atanh(1.0f), kInf);
  EXPECT_BITS(m::atanh(-1.0f), -kInf);
  EXPECT_BITS(m::atanh(1.0000001f), kNaN);
  EXPECT_BITS(m::atanh(-kInf), kNaN);
}

TEST(GlslMathSpecial, ExpLog) {
  for (const Unary f : {m::exp, m::exp2}) {
    EXPECT_BITS(f(0.0f), 1.0f);
    EXPECT_BITS(f(-0.0f), 1.0f);
    EXPECT_BITS(f(-kInf), 0.0f);
    EXPECT_BITS(f(kInf), kInf);
    EXPECT_BITS(f(200.0f), kInf);
    EXPECT_BITS(f(-200.0f), 0.0f);
    EXPECT_BITS(f(kNaN), kNaN);
  }
  for (int k = -149; k <= 127; ++k) {  // exact at integers, denormals included
    EXPECT_BITS(m::exp2(float(k)), std::ldexp(1.0f, k));
    EXPECT_BITS(m::log2(std::ldexp(1.0f, k)), float(k));
  }
  EXPECT_BITS(m::exp2(128.0f), kInf);
  EXPECT_BITS(m::exp2(-150.0f), 0.0f);  // 2^-150 is halfway to the smallest denormal: to even
  EXPECT_BITS(m::exp(88.72283f), float(std::exp(double(88.72283f))));  // near FLT_MAX
  EXPECT_BITS(m::exp(88.72284f), kInf);
  for (const Unary f : {m::log, m::log2}) {
    EXPECT_BITS(f(1.0f), 0.0f);
    EXPECT_BITS(f(0.0f), -kInf);
    EXPECT_BITS(f(-0.0f), -kInf);
    EXPECT_BITS(f(-FLT_TRUE_MIN), kNaN);
    EXPECT_BITS(f(-1.0f), kNaN);
    EXPECT_BITS(f(-kInf), kNaN);
    EXPECT_BITS(f(kInf), kInf);
    EXPECT_BITS(f(kNaN), kNaN);
  }
}

TEST(GlslMathSpecial, Pow) {
  EXPECT_BITS(m::pow(kNaN, 0.0f), 1.0f);
  EXPECT_BITS(m::pow(kNaN, -0.0f), 1.0f);
  EXPECT_BITS(m::pow(1.0f, kNaN), 1.0f);
  EXPECT_BITS(m::pow(1.0f, -kInf), 1.0f);
  EXPECT_BITS(m::pow(kNaN, 1.0f), kNaN);
  EXPECT_BITS(m::pow(2.0f, kNaN), kNaN);
  // Zero base.
  EXPECT_BITS(m::pow(0.0f, -3.0f), kInf);
  EXPECT_BITS(m::pow(-0.0f, -3.0f), -kInf);
  EXPECT_BITS(m::pow(-0.0f, -2.0f), kInf);
  EXPECT_BITS(m::pow(-0.0f, -0.5f), kInf);
  EXPECT_BITS(m::pow(-0.0f, -kInf), kInf);
  EXPECT_BITS(m::pow(0.0f, 3.0f), 0.0f);
  EXPECT_BITS(m::pow(-0.0f, 3.0f), -0.0f);
  EXPECT_BITS(m::pow(-0.0f, 2.0f), 0.0f);
  EXPECT_BITS(m::pow(-0.0f, 0.5f), 0.0f);
  EXPECT_BITS(m::pow(-0.0f, kInf), 0.0f);
  // Infinite exponent.
  EXPECT_BITS(m::pow(-1.0f, kInf), 1.0f);
  EXPECT_BITS(m::pow(-1.0f, -kInf), 1.0f);
  EXPECT_BITS(m::pow(0.5f, kInf), 0.0f);
  EXPECT_BITS(m::pow(-0.5f, -kInf), kInf);
  EXPECT_BITS(m::pow(2.0f, kInf), kInf);
  EXPECT_BITS(m::pow(-2.0f, -kInf), 0.0f);
  // Infinite base.
  EXPECT_BITS(m::pow(-kInf, -3.0f), -0.0f);
  EXPECT_BITS(m::pow(-kInf, -2.0f), 0.0f);
  EXPECT_BITS(m::pow(-kInf, 3.0f), -kInf);
  EXPECT_BITS(m::pow(-kInf, 0.5f), kInf);
  EXPECT_BITS(m::pow(kInf, -1.0f), 0.0f);
  EXPECT_BITS(m::pow(kInf, 0.5f), kInf);
  // Negative finite base: integer exponents only.
  EXPECT_BITS(m::pow(-2.0f, 3.0f), -8.0f);
  EXPECT_BITS(m::pow(-2.0f, -2.0f), 0.25f);
  EXPECT_BITS(m::pow(-2.0f, 0.5f), kNaN);
  EXPECT_BITS(m::pow(-3.0f, 16777216.0f), kInf);  // 2^24: even
  EXPECT_BITS(m::pow(-1.0f, 16777215.0f), -1.0f);  // 2^24 - 1: odd
  // Exact results stay exact; over- and underflow.
  EXPECT_BITS(m::pow(2.0f, 10.0f), 1024.0f);
  EXPECT_BITS(m::pow(10.0f, 3.0f), 1000.0f);
  EXPECT_BITS(m::pow(4.0f, 0.5f), 2.0f);
  EXPECT_BITS(m::pow(3.0f, 1.0f), 3.0f);
  EXPECT_BITS(m::pow(2.0f, -149.0f), FLT_TRUE_MIN);
  EXPECT_BITS(m::pow(10.0f, 39.0f), kInf);
  EXPECT_BITS(m::pow(-10.0f, 39.0f), -kInf);
  EXPECT_BITS(m::pow(10.0f, -46.0f), 0.0f);
  EXPECT_BITS(m::pow(-10.0f, -47.0f), -0.0f);
}

// Fixed inputs per function, from integers only: 5000 arbitrary bit patterns (NaNs, infinities,
// denormals and all) and 5000 floats between lo and hi.
std::vector<float> hash_inputs(float lo, float hi, uint64_t seed) {
  uint64_t s = seed;
  auto next = [&] {  // splitmix64
    uint64_t z = (s += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
  };
  std::vector<float> v;
  for (int i = 0; i < 5000; ++i) v.push_back(std::bit_cast<float>(uint32_t(next())));
  const int64_t klo = key(lo), span = key(hi) - klo + 1;
  for (int i = 0; i < 5000; ++i) v.push_back(from_key(klo + int64_t(next() % uint64_t(span))));
  return v;
}

uint64_t fnv1a(const std::vector<float>& out) {
  uint64_t h = 0xcbf29ce484222325u;
  for (const float f : out) {
    const uint32_t b = std::bit_cast<uint32_t>(f);
    for (int i = 0; i < 32; i += 8) h = (h ^ ((b >> i) & 0xffu)) * 0x100000001b3u;
  }
  return h;
}

using ArrayUnary = void (*)(const float*, float*, int);
using ArrayBinary = void (*)(const float*, const float*, float*, int);

struct UnaryCase {
  const char* name;
  Unary f;
  ArrayUnary f_n;
  float lo, hi;
  uint64_t hash;
};

struct BinaryCase {
  const char* name;
  float (*f)(float, float);
  ArrayBinary f_n;
  float lo_a, hi_a, lo_b, hi_b;
  uint64_t hash;
};

// The hashes were computed once; a change in any output bit on any machine changes them.
const UnaryCase kUnary[] = {
    {"sin", m::sin, m::sin_n, -1e5f, 1e5f, 0x73a9023ce2aff5bd},
    {"cos", m::cos, m::cos_n, -1e5f, 1e5f, 0x83f1c3c1cfe5a28f},
    {"tan", m::tan, m::tan_n, -1e5f, 1e5f, 0xfa203699e1bc62e4},
    {"asin", m::asin, m::asin_n, -1, 1, 0x9d1c705e16d1119c},
    {"acos", m::acos, m::acos_n, -1, 1, 0xeb0796f3e3f5f253},
    {"atan", m::atan, m::atan_n, -1e3f, 1e3f, 0x0f2626220e4b5841},
    {"sinh", m::sinh, m::sinh_n, -90, 90, 0x20a641063452ad37},
    {"cosh", m::cosh, m::cosh_n, -90, 90, 0x50f745330ce70c62},
    {"tanh", m::tanh, m::tanh_n, -10, 10, 0x420123778d23524e},
    {"asinh", m::asinh, m::asinh_n, -1e3f, 1e3f, 0xebc99ddc8c2d2ff4},
    {"acosh", m::acosh, m::acosh_n, 1, 1e3f, 0x3ad8d5ee39e06a92},
    {"atanh", m::atanh, m::atanh_n, -1, 1, 0x21947537463488cd},
    {"exp", m::exp, m::exp_n, -104, 89, 0xff0f19fd0d2c89ce},
    {"exp2", m::exp2, m::exp2_n, -151, 128, 0xca59d178eb200971},
    {"log", m::log, m::log_n, 0, 1e3f, 0x861a2bd1bbabf6de},
    {"log2", m::log2, m::log2_n, 0, 1e3f, 0x167a80c7d1044dca},
};
const BinaryCase kBinary[] = {
    {"pow", m::pow, m::pow_n, 0, 16, -30, 30, 0x8613d4a3d59d0bcd},
    {"atan2", m::atan2, m::atan2_n, -10, 10, -10, 10, 0xe11b42f828f9f1a7},
};

TEST(GlslMathDeterminism, OutputHashes) {
  uint64_t seed = 1;
  for (const UnaryCase& c : kUnary) {
    std::vector<float> out;
    for (const float x : hash_inputs(c.lo, c.hi, seed++)) out.push_back(c.f(x));
    EXPECT_EQ(fnv1a(out), c.hash) << c.name << ": 0x" << std::hex << fnv1a(out);
  }
  for (const BinaryCase& c : kBinary) {
    const std::vector<float> a = hash_inputs(c.lo_a, c.hi_a, seed++);
    const std::vector<float> b = hash_inputs(c.lo_b, c.hi_b, seed++);
    std::vector<float> out;
    for (std::size_t i = 0; i < a.size(); ++i) out.push_back(c.f(a[i], b[i]));
    EXPECT_EQ(fnv1a(out), c.hash) << c.name << ": 0x" << std::hex << fnv1a(out);
  }
}

TEST(GlslMathDeterminism, ArraysMatchScalar) {
  uint64_t seed = 1;
  for (const UnaryCase& c : kUnary) {
    const std::vector<float> x = hash_inputs(c.lo, c.hi, seed++);
    std::vector<float> out(x.size());
    c.f_n(x.data(), out.data(), int(x.size()) - 1);  // an odd count: a loop's tail too
    EXPECT_EQ(out.back(), 0.0f) << c.name << ": wrote past n";
    for (std::size_t i = 0; i + 1 < x.size(); ++i)
      ASSERT_EQ(std::bit_cast<uint32_t>(out[i]), std::bit_cast<uint32_t>(c.f(x[i])))
          << c.name << "(" << x[i] << ")";
  }
  for (const BinaryCase& c : kBinary) {
    const std::vector<float> a = hash_inputs(c.lo_a, c.hi_a, seed++);
    const std::vector<float> b = hash_inputs(c.lo_b, c.hi_b, seed++);
    std::vector<float> out(a.size());
    c.f_n(a.data(), b.data(), out.data(), int(a.size()) - 1);
    EXPECT_EQ(out.back(), 0.0f) << c.name << ": wrote past n";
    for (std::size_t i = 0; i + 1 < a.size(); ++i)
      ASSERT_EQ(std::bit_cast<uint32_t>(out[i]), std::bit_cast<uint32_t>(c.f(a[i], b[i])))
          << c.name << "(" << a[i] << ", " << b[i] << ")";
  }
}

}  // namespace
