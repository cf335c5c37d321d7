// The SPIR-V executor on small programs: every value checked per lane, to the bit, against values
// computed here by hand (in the operation order the executor documents) or by tessref's math
// library. Kernels are vertex shaders (per-lane inputs and outputs) unless noted.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <malloc.h>  // mallinfo2

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "shader/glsl_math.h"
#include "shader_test_util.h"

namespace tessref::shader::test {
namespace {

using ::testing::HasSubstr;

constexpr std::int32_t kIntMin = std::numeric_limits<std::int32_t>::min();
constexpr std::int32_t kIntMax = std::numeric_limits<std::int32_t>::max();
const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();
const double kNaNd = std::numeric_limits<double>::quiet_NaN();

// Equal bits, or both NaN (hardware NaNs from sqrt(-1) or 0/0 carry a sign bit that the host's
// constant folding may not give).
::testing::AssertionResult same(float want, float got) {
  if (bits(want) == bits(got) || (std::isnan(want) && std::isnan(got))) return ::testing::AssertionSuccess();
  char text[96];
  std::snprintf(text, sizeof text, "want %a (0x%08x), got %a (0x%08x)", double(want), bits(want), double(got),
                bits(got));
  return ::testing::AssertionFailure() << text;
}

// ---------------------------------------------------------------------------------------------
// Integers

TEST(Executor, IntegerArithmeticWrapsAndDivisionByZeroIsZero) {
  Kernel k(R"(#version 450
layout(location = 0) in ivec2 a;
layout(location = 1) in uvec2 u;
out int ri[10];
out uint ru[7];
void main() {
  int x = a.x, y = a.y;
  ri[0] = x + y;
  ri[1] = x - y;
  ri[2] = x * y;
  ri[3] = x / y;
  ri[4] = x % y;
  ri[5] = -x;
  ri[6] = abs(x);
  ri[7] = sign(x);
  ri[8] = min(x, y);
  ri[9] = clamp(x, -4, 4);
  ru[0] = u.x + u.y;
  ru[1] = u.x - u.y;
  ru[2] = u.x * u.y;
  ru[3] = u.x / u.y;
  ru[4] = u.x % u.y;
  ru[5] = max(u.x, u.y);
  ru[6] = min(u.x, u.y);
}
)");
  struct Case {
    std::int32_t x, y;
    std::array<std::int32_t, 10> want;  // +, -, *, /, %, neg, abs, sign, min, clamp(-4, 4)
  };
  // GLSL's % on ints is OpSMod: the result has the divisor's sign.
  const std::vector<Case> cases = {
      {7, 2, {9, 5, 14, 3, 1, -7, 7, 1, 2, 4}},
      {-7, 2, {-5, -9, -14, -3, 1, 7, 7, -1, -7, -4}},
      {7, -2, {5, 9, -14, -3, -1, -7, 7, 1, -2, 4}},
      {-6, -3, {-9, -3, 18, 2, 0, 6, 6, -1, -6, -4}},
      {5, 0, {5, 5, 0, 0, 0, -5, 5, 1, 0, 4}},          // division by zero: 0
      {kIntMin, -1, {kIntMax, kIntMin + 1, kIntMin, kIntMin, 0, kIntMin, kIntMin, -1, kIntMin, -4}},
      {kIntMax, 1, {kIntMin, kIntMax - 1, kIntMax, kIntMax, 0, -kIntMax, kIntMax, 1, 1, 4}},
      {65536, 65536, {131072, 0, 0, 1, 0, -65536, 65536, 1, 65536, 4}},
      {0, 3, {3, -3, 0, 0, 0, 0, 0, 0, 0, 0}},
      {kIntMin, 0, {kIntMin, kIntMin, 0, 0, 0, kIntMin, kIntMin, -1, kIntMin, -4}},
  };
  struct UCase {
    std::uint32_t x, y;
    std::array<std::uint32_t, 7> want;  // +, -, *, /, %, max, min
  };
  const std::vector<UCase> ucases = {
      {7u, 2u, {9u, 5u, 14u, 3u, 1u, 7u, 2u}},
      {3u, 5u, {8u, 0xfffffffeu, 15u, 0u, 3u, 5u, 3u}},
      {0xffffffffu, 2u, {1u, 0xfffffffdu, 0xfffffffeu, 0x7fffffffu, 1u, 0xffffffffu, 2u}},
      {9u, 0u, {9u, 9u, 0u, 0u, 0u, 9u, 0u}},  // division by zero: 0
      {0x80000000u, 0x80000000u, {0u, 0u, 0u, 1u, 0u, 0x80000000u, 0x80000000u}},
  };
  const int n = int(std::max(cases.size(), ucases.size()));
  k.begin(n);
  for (int l = 0; l < n; ++l) {
    const Case& c = cases[std::size_t(l) % cases.size()];
    const UCase& u = ucases[std::size_t(l) % ucases.size()];
    k.set_i32("a", l, 0, c.x);
    k.set_i32("a", l, 1, c.y);
    k.set("u", l, 0, u.x);
    k.set("u", l, 1, u.y);
  }
  k.run();
  for (int l = 0; l < n; ++l) {
    const Case& c = cases[std::size_t(l) % cases.size()];
    const UCase& u = ucases[std::size_t(l) % ucases.size()];
    for (int i = 0; i < 10; ++i)
      EXPECT_EQ(k.i32("ri", l, std::uint32_t(i)), c.want[std::size_t(i)])
          << "lane " << l << ": ri[" << i << "] of (" << c.x << ", " << c.y << ")";
    for (int i = 0; i < 7; ++i)
      EXPECT_EQ(k.u32("ru", l, std::uint32_t(i)), u.want[std::size_t(i)])
          << "lane " << l << ": ru[" << i << "] of (" << u.x << "u, " << u.y << "u)";
  }
}

TEST(Executor, ShiftsAndBitwiseOperations) {
  Kernel k(R"(#version 450
layout(location = 0) in ivec2 a;
layout(location = 1) in uvec2 u;
out int ri[5];
out uint ru[6];
void main() {
  ri[0] = a.x >> a.y;   // arithmetic
  ri[1] = a.x << a.y;
  ri[2] = a.x & ~a.y;
  ri[3] = a.x | a.y;
  ri[4] = a.x ^ a.y;
  ru[0] = u.x >> u.y;   // logical
  ru[1] = u.x << u.y;
  ru[2] = ~u.x;
  ru[3] = u.x >> a.y;   // int shift amount on a uint
  ru[4] = uint(a.x) >> u.y;
  ru[5] = u.x & u.y | u.x ^ 0x0f0fu;
}
)");
  struct Case {
    std::int32_t x, s;
    std::uint32_t ux, us;
  };
  const std::vector<Case> cases = {
      {-16, 2, 0x80000000u, 31u},
      {-1, 31, 0xf0f0f0f0u, 4u},
      {1, 31, 1u, 31u},
      {0x12345678, 0, 0x12345678u, 0u},
      {kIntMin, 1, 0xffffffffu, 16u},
      {5, 3, 0x0000ffffu, 8u},
  };
  const int n = int(cases.size());
  k.begin(n);
  for (int l = 0; l < n; ++l) {
    k.set_i32("a", l, 0, cases[l].x);
    k.set_i32("a", l, 1, cases[l].s);
    k.set("u", l, 0, cases[l].ux);
    k.set("u", l, 1, cases[l].us);
  }
  k.run();
  const std::vector<std::array<std::int32_t, 5>> want_i = {
      {-4, -64, -16 & ~2, -16 | 2, -16 ^ 2},
      {-1, kIntMin, -1 & ~31, -1, -1 ^ 31},
      {0, kIntMin, 0, 31, 30},
      {0x12345678, 0x12345678, 0x12345678, 0x12345678, 0x12345678},
      {kIntMin / 2, 0, kIntMin, kIntMin | 1, kIntMin | 1},
      {0, 40, 4, 7, 6},
  };
  const std::vector<std::array<std::uint32_t, 6>> want_u = {
      {1u, 0u, 0x7fffffffu, 0x20000000u, 1u, 0x80000f0fu},
      {0x0f0f0f0fu, 0x0f0f0f00u, 0x0f0f0f0fu, 1u, 0x0fffffffu, 0xf0f0ffffu},
      {0u, 0x80000000u, 0xfffffffeu, 0u, 0u, 0x00000f0fu},
      {0x12345678u, 0x12345678u, ~0x12345678u, 0x12345678u, 0x12345678u, 0x12345977u},
      {0xffffu, 0xffff0000u, 0u, 0x7fffffffu, 0x8000u, 0xfffff0f0u},
      {0xffu, 0x00ffff00u, 0xffff0000u, 0x1fffu, 0u, 0x0000f0f8u},
  };
  for (int l = 0; l < n; ++l) {
    for (int i = 0; i < 5; ++i) EXPECT_EQ(k.i32("ri", l, std::uint32_t(i)), want_i[l][std::size_t(i)]) << "lane " << l << " ri[" << i << "]";
    for (int i = 0; i < 6; ++i) EXPECT_EQ(k.u32("ru", l, std::uint32_t(i)), want_u[l][std::size_t(i)]) << "lane " << l << " ru[" << i << "]";
  }
}

// docs/executor.md: "shift by 32 or more: the count modulo 32" (GLSL leaves it undefined).
TEST(Executor, ShiftCountsAreTakenModulo32) {
  Kernel k(R"(#version 450
layout(location = 0) in ivec2 a;  // value, count
layout(location = 1) in uint u;
out int r_shl;
out int r_sar;
out uint r_shr;
void main() {
  r_shl = a.x << a.y;
  r_sar = a.x >> a.y;
  r_shr = u >> a.y;
}
)");
  struct Case {
    std::int32_t x, count;
    std::uint32_t u;
    std::int32_t shl, sar;
    std::uint32_t shr;
  };
  const std::vector<Case> cases = {
      {1, 32, 0x80000000u, 1, 1, 0x80000000u},
      {1, 33, 0x80000000u, 2, 0, 0x40000000u},
      {-8, 33, 0xf0u, -16, -4, 0x78u},
      {3, 63, 0x80000000u, kIntMin, 0, 1u},
      {-1, -1, 0xffffffffu, kIntMin, -1, 1u},  // a count of -1 is 31
      {5, 100, 0x100u, 80, 0, 0x10u},          // 100 % 32 = 4
  };
  const int n = int(cases.size());
  k.begin(n);
  for (int l = 0; l < n; ++l) {
    k.set_i32("a", l, 0, cases[l].x);
    k.set_i32("a", l, 1, cases[l].count);
    k.set("u", l, 0, cases[l].u);
  }
  k.run();
  for (int l = 0; l < n; ++l) {
    SCOPED_TRACE("lane " + std::to_string(l) + ": count " + std::to_string(cases[l].count));
    EXPECT_EQ(k.i32("r_shl", l), cases[l].shl);
    EXPECT_EQ(k.i32("r_sar", l), cases[l].sar);
    EXPECT_EQ(k.u32("r_shr", l), cases[l].shr);
  }
}

TEST(Executor, BitfieldOperationsAndBitCounts) {
  Kernel k(R"(#version 450
layout(location = 0) in int x;
layout(location = 1) in uint u;
layout(location = 2) in ivec2 oc;  // offset, bits
out int ri[5];
out uint ru[4];
void main() {
  ri[0] = bitfieldExtract(x, oc.x, oc.y);
  ri[1] = findLSB(x);
  ri[2] = findMSB(x);
  ri[3] = bitCount(x);
  ri[4] = bitfieldInsert(x, -1, oc.x, oc.y);
  ru[0] = bitfieldExtract(u, oc.x, oc.y);
  ru[1] = bitfieldReverse(u);
  ru[2] = bitfieldInsert(u, 0u, oc.x, oc.y);
  ru[3] = uint(findMSB(u) + 1000 * findLSB(u) + 1000000 * bitCount(u));
}
)");
  struct Case {
    std::int32_t x;
    std::uint32_t u;
    std::int32_t offset, count;
    std::array<std::int32_t, 5> want_i;   // extract, findLSB, findMSB, bitCount, insert(-1)
    std::array<std::uint32_t, 4> want_u;  // extract, reverse, insert(0), msb + 1000 lsb + 1e6 count
  };
  auto packed = [](int msb, int lsb, int count) { return std::uint32_t(msb + 1000 * lsb + 1000000 * count); };
  const std::vector<Case> cases = {
      // 0xf80 >> 7 = 0b11111: signed, the field's top bit extends.
      {0xf80, 0xf80u, 7, 5, {-1, 7, 11, 5, 0xf80}, {31u, 0x01f00000u, 0u, packed(11, 7, 5)}},
      {0, 0u, 4, 8, {0, -1, -1, 0, 0xff0}, {0u, 0u, 0u, packed(-1, -1, 0)}},
      {-1, 0xffffffffu, 0, 32, {-1, 0, -1, 32, -1}, {0xffffffffu, 0xffffffffu, 0u, packed(31, 0, 32)}},
      {kIntMin, 0x80000000u, 31, 1, {-1, 31, 30, 1, kIntMin}, {1u, 1u, 0u, packed(31, 31, 1)}},
      {0x12345678, 0x12345678u, 4, 8, {0x67, 3, 28, 13, 0x12345ff8},
       {0x67u, 0x1e6a2c48u, 0x12345008u, packed(28, 3, 13)}},
      {-2, 8u, 1, 0, {0, 1, 0, 31, -2}, {0u, 0x10000000u, 8u, packed(3, 3, 1)}},  // 0 bits: 0
      {0x70, 0x70u, 4, 3, {-1, 4, 6, 3, 0x70}, {7u, 0x0e000000u, 0u, packed(6, 4, 3)}},
      {1, 1u, 0, 1, {-1, 0, 0, 1, 1}, {1u, 0x80000000u, 0u, packed(0, 0, 1)}},
  };
  const int n = int(cases.size());
  k.begin(n);
  for (int l = 0; l < n; ++l) {
    k.set_i32("x", l, 0, cases[l].x);
    k.set("u", l, 0, cases[l].u);
    k.set_i32("oc", l, 0, cases[l].offset);
    k.set_i32("oc", l, 1, cases[l].count);
  }
  k.run();
  for (int l = 0; l < n; ++l) {
    for (int i = 0; i < 5; ++i) EXPECT_EQ(k.i32("ri", l, std::uint32_t(i)), cases[l].want_i[std::size_t(i)]) << "lane " << l << " ri[" << i << "]";
    for (int i = 0; i < 4; ++i) EXPECT_EQ(k.u32("ru", l, std::uint32_t(i)), cases[l].want_u[std::size_t(i)]) << "lane " << l << " ru[" << i << "]";
  }
}

// ---------------------------------------------------------------------------------------------
// Floats, conversions and booleans

TEST(Executor, FloatArithmeticKeepsIeeeSpecialValues) {
  Kernel k(R"(#version 450
layout(location = 0) in vec2 a;
out float r[7];
void main() {
  r[0] = a.x + a.y;
  r[1] = a.x - a.y;
  r[2] = a.x * a.y;
  r[3] = a.x / a.y;
  r[4] = -a.x;
  r[5] = a.x + 0.0;   // -0.0 + 0.0 = +0.0: not folded away
  r[6] = mod(a.x, a.y);
}
)");
  const float tiny = std::numeric_limits<float>::denorm_min();
  const std::vector<std::array<float, 2>> in = {
      {1.5f, 0.25f}, {1.0f, 0.0f}, {-1.0f, 0.0f}, {0.0f, 0.0f}, {kInf, kInf}, {-0.0f, 1.0f},
      {kNaN, 1.0f}, {tiny, 0.5f}, {std::ldexp(1.0f, -126), -std::ldexp(1.0f, -127)}, {3.0e38f, 10.0f}, {0.1f, 0.2f}, {-7.5f, 2.0f},
      {7.5f, -2.0f}, {1.0f, 3.0f}};
  const int n = int(in.size());
  k.begin(n);
  for (int l = 0; l < n; ++l) {
    k.set_f32("a", l, 0, in[l][0]);
    k.set_f32("a", l, 1, in[l][1]);
  }
  k.run();
  for (int l = 0; l < n; ++l) {
    const float x = in[l][0], y = in[l][1];
    SCOPED_TRACE("lane " + std::to_string(l));
    EXPECT_TRUE(same(x + y, k.f32("r", l, 0)));
    EXPECT_TRUE(same(x - y, k.f32("r", l, 1)));
    EXPECT_TRUE(same(x * y, k.f32("r", l, 2)));
    EXPECT_TRUE(same(x / y, k.f32("r", l, 3)));
    EXPECT_TRUE(same(-x, k.f32("r", l, 4)));
    EXPECT_TRUE(same(x + 0.0f, k.f32("r", l, 5)));
    EXPECT_TRUE(same(x - y * std::floor(x / y), k.f32("r", l, 6)));
  }
  // The special values spelled out.
  EXPECT_EQ(k.f32("r", 1, 3), kInf);
  EXPECT_EQ(k.f32("r", 2, 3), -kInf);
  EXPECT_TRUE(std::isnan(k.f32("r", 3, 3)));
  EXPECT_TRUE(std::isnan(k.f32("r", 4, 1)));       // inf - inf
  EXPECT_EQ(bits(k.f32("r", 5, 5)), 0u);           // -0 + 0 = +0
  EXPECT_EQ(bits(k.f32("r", 5, 4)), 0u);           // -(-0) = +0
  EXPECT_EQ(bits(k.f32("r", 7, 2)), 0u);           // denorm_min * 0.5 rounds to even: 0
  EXPECT_EQ(k.f32("r", 8, 0), std::ldexp(1.0f, -127));  // a denormal result: no flush to zero
  EXPECT_EQ(bits(k.f32("r", 7, 3)), 0x00000002u);        // denormal inputs: no flush either
  EXPECT_EQ(bits(k.f32("r", 7, 4)), 0x80000001u);
  EXPECT_EQ(k.f32("r", 9, 2), kInf);               // overflow
  EXPECT_EQ(k.f32("r", 11, 6), 0.5f);              // mod(-7.5, 2) = 0.5
  EXPECT_EQ(k.f32("r", 12, 6), -0.5f);             // mod(7.5, -2) = -0.5
  EXPECT_EQ(k.f32("r", 13, 3), 1.0f / 3.0f);
}

TEST(Executor, FloatToIntegerConversionsAreDefined) {
  // docs/executor.md: NaN and out-of-range values give INT_MIN; to uint, 0 below 0 (and for NaN),
  // 0xffffffff above.
  Kernel k(R"(#version 450
layout(location = 0) in float f;
layout(location = 1) in double d;
layout(location = 2) in int i;
layout(location = 3) in uint u;
out int r_fi;
out uint r_fu;
out int r_di;
out uint r_du;
out float r_if;
out float r_uf;
out double r_id;
out double r_ud;
void main() {
  r_fi = int(f);
  r_fu = uint(f);
  r_di = int(d);
  r_du = uint(d);
  r_if = float(i);
  r_uf = float(u);
  r_id = double(i);
  r_ud = double(u);
}
)");
  struct Case {
    float f;
    std::int32_t fi;
    std::uint32_t fu;
    double d;
    std::int32_t di;
    std::uint32_t du;
  };
  const std::vector<Case> cases = {
      {kNaN, kIntMin, 0u, kNaNd, kIntMin, 0u},
      {kInf, kIntMin, 0xffffffffu, 1e300, kIntMin, 0xffffffffu},
      {-kInf, kIntMin, 0u, -1e300, kIntMin, 0u},
      {3e9f, kIntMin, 3000000000u, 2147483648.0, kIntMin, 2147483648u},
      {-3e9f, kIntMin, 0u, -2147483649.0, kIntMin, 0u},
      {2147483520.0f, 2147483520, 2147483520u, 2147483647.9, kIntMax, 2147483647u},
      {2147483648.0f, kIntMin, 2147483648u, -2147483648.9, kIntMin, 0u},
      {-2147483648.0f, kIntMin, 0u, 4294967295.9, kIntMin, 0xffffffffu},
      {-1.9f, -1, 0u, -1.9, -1, 0u},
      {1.9f, 1, 1u, 1.9, 1, 1u},
      {-0.5f, 0, 0u, -0.5, 0, 0u},
      {-0.0f, 0, 0u, -0.0, 0, 0u},
      {4294967040.0f, kIntMin, 4294967040u, 123456789.75, 123456789, 123456789u},
  };
  const std::vector<std::int32_t> ints = {16777217, 16777219, kIntMin, kIntMax, -1, 0, 7};
  const std::vector<std::uint32_t> uints = {0xffffffffu, 16777217u, 0x80000000u, 0u, 0x80000080u, 1u, 0x7fffffc0u};
  const int n = int(cases.size());
  k.begin(n);
  for (int l = 0; l < n; ++l) {
    k.set_f32("f", l, 0, cases[l].f);
    k.set_f64("d", l, 0, cases[l].d);
    k.set_i32("i", l, 0, ints[std::size_t(l) % ints.size()]);
    k.set("u", l, 0, uints[std::size_t(l) % uints.size()]);
  }
  k.run();
  for (int l = 0; l < n; ++l) {
    const Case& c = cases[l];
    SCOPED_TRACE("lane " + std::to_string(l) + ": f = " + std::to_string(c.f) + ", d = " + std::to_string(c.d));
    EXPECT_EQ(k.i32("r_fi", l), c.fi);
    EXPECT_EQ(k.u32("r_fu", l), c.fu);
    EXPECT_EQ(k.i32("r_di", l), c.di);
    EXPECT_EQ(k.u32("r_du", l), c.du);
    const std::int32_t i = ints[std::size_t(l) % ints.size()];
    const std::uint32_t u = uints[std::size_t(l) % uints.size()];
    EXPECT_EQ(bits(k.f32("r_if", l)), bits(float(i))) << i;  // round to nearest even
    EXPECT_EQ(bits(k.f32("r_uf", l)), bits(float(u))) << u;
    EXPECT_EQ(k.f64("r_id", l), double(i));
    EXPECT_EQ(k.f64("r_ud", l), double(u));
  }
  // Rounding spelled out: 16777217 and 16777219 are halfway; 0xffffffff rounds up to 2^32.
  EXPECT_EQ(k.f32("r_if", 0), 16777216.0f);
  EXPECT_EQ(k.f32("r_if", 1), 16777220.0f);
  EXPECT_EQ(k.f32("r_uf", 0), 4294967296.0f);
}

// docs/executor.md: "to uint: 0 below 0, 0xffffffff above" (executor.h's comment says 0 for both).
TEST(Executor, UnsignedConversionSaturatesAboveTheRange) {
  Kernel k(R"(#version 450
layout(location = 0) in float f;
layout(location = 1) in double d;
out uint r_fu;
out uint r_du;
void main() { r_fu = uint(f); r_du = uint(d); }
)");
  const float fs[4] = {5e9f, kInf, 4294967296.0f, kNaN};
  const double ds[4] = {5e9, std::numeric_limits<double>::infinity(), 4294967296.0, kNaNd};
  const std::uint32_t want[4] = {0xffffffffu, 0xffffffffu, 0xffffffffu, 0u};
  k.begin(4);
  for (int l = 0; l < 4; ++l) {
    k.set_f32("f", l, 0, fs[l]);
    k.set_f64("d", l, 0, ds[l]);
  }
  k.run();
  for (int l = 0; l < 4; ++l) {
    EXPECT_EQ(k.u32("r_fu", l), want[l]) << fs[l];
    EXPECT_EQ(k.u32("r_du", l), want[l]) << ds[l];
  }
}

TEST(Executor, ComparisonsAndBooleans) {
  Kernel k(R"(#version 450
layout(location = 0) in vec2 a;
layout(location = 1) in ivec2 b;
out int r[16];
void main() {
  float x = a.x, y = a.y;
  bool p = b.x != 0, q = b.y != 0;
  r[0] = int(x < y);
  r[1] = int(x <= y);
  r[2] = int(x > y);
  r[3] = int(x >= y);
  r[4] = int(x == y);
  r[5] = int(x != y);
  r[6] = int(isnan(x)) + 2 * int(isinf(x));
  r[7] = int(p && q) + 2 * int(p || q) + 4 * int(p ^^ q) + 8 * int(!p) + 16 * int(p == q);
  bvec3 v = bvec3(p, q, x < y);
  r[8] = int(any(v)) + 2 * int(all(v)) + 4 * int(any(not(v)));
  bvec2 lt = lessThan(a, vec2(y, x));
  r[9] = int(lt.x) + 2 * int(lt.y);
  r[10] = p ? b.x : b.y;                       // scalar select
  ivec2 m = mix(ivec2(1, 2), ivec2(3, 4), bvec2(p, q));
  r[11] = m.x * 10 + m.y;                      // per-component select
  r[12] = int(b.x < b.y) + 2 * int(uint(b.x) < uint(b.y));  // signed and unsigned order
  r[13] = int(bool(b.x)) + 2 * int(float(p) == 1.0);
  r[14] = int(equal(b, ivec2(0)).x) + 2 * int(notEqual(b, ivec2(0)).y);
  r[15] = int(x < y ? true : false);
}
)");
  struct Case {
    float x, y;
    std::int32_t p, q;
  };
  const std::vector<Case> cases = {
      {1.0f, 2.0f, 1, 0}, {2.0f, 1.0f, 0, 1}, {1.0f, 1.0f, 1, 1}, {kNaN, 1.0f, 0, 0},
      {kNaN, kNaN, 5, -1}, {-0.0f, 0.0f, -1, 5}, {kInf, kNaN, 0, 7}, {-kInf, kInf, 3, 0}};
  const int n = int(cases.size());
  k.begin(n);
  for (int l = 0; l < n; ++l) {
    k.set_f32("a", l, 0, cases[l].x);
    k.set_f32("a", l, 1, cases[l].y);
    k.set_i32("b", l, 0, cases[l].p);
    k.set_i32("b", l, 1, cases[l].q);
  }
  k.run();
  for (int l = 0; l < n; ++l) {
    const Case& c = cases[l];
    const float x = c.x, y = c.y;
    const bool p = c.p != 0, q = c.q != 0;
    SCOPED_TRACE("lane " + std::to_string(l));
    // IEEE comparisons: every ordered comparison with NaN is false, != is true.
    EXPECT_EQ(k.i32("r", l, 0), int(x < y));
    EXPECT_EQ(k.i32("r", l, 1), int(x <= y));
    EXPECT_EQ(k.i32("r", l, 2), int(x > y));
    EXPECT_EQ(k.i32("r", l, 3), int(x >= y));
    EXPECT_EQ(k.i32("r", l, 4), int(x == y));
    EXPECT_EQ(k.i32("r", l, 5), int(x != y));
    EXPECT_EQ(k.i32("r", l, 6), int(std::isnan(x)) + 2 * int(std::isinf(x)));
    EXPECT_EQ(k.i32("r", l, 7), int(p && q) + 2 * int(p || q) + 4 * int(p != q) + 8 * int(!p) + 16 * int(p == q));
    const bool v[3] = {p, q, x < y};
    const bool any = v[0] || v[1] || v[2], all = v[0] && v[1] && v[2];
    EXPECT_EQ(k.i32("r", l, 8), int(any) + 2 * int(all) + 4 * int(!all));
    EXPECT_EQ(k.i32("r", l, 9), int(x < y) + 2 * int(y < x));
    EXPECT_EQ(k.i32("r", l, 10), p ? c.p : c.q);
    EXPECT_EQ(k.i32("r", l, 11), (p ? 3 : 1) * 10 + (q ? 4 : 2));
    EXPECT_EQ(k.i32("r", l, 12), int(c.p < c.q) + 2 * int(std::uint32_t(c.p) < std::uint32_t(c.q)));
    EXPECT_EQ(k.i32("r", l, 13), int(p) + 2 * int(p));
    EXPECT_EQ(k.i32("r", l, 14), int(c.p == 0) + 2 * int(c.q != 0));
    EXPECT_EQ(k.i32("r", l, 15), int(x < y));
  }
}

// ---------------------------------------------------------------------------------------------
// Divergent control flow: every lane's result is that of running it alone.

const char* kControlFlow = R"(#version 450
layout(location = 0) in int n;  // a per-lane loop trip count
layout(location = 1) in int k;  // where the first loop breaks
layout(location = 2) in int s;  // switch selector
out int r_loop;
out int r_last;
out int r_nested;
out int r_switch;
out int r_func;
out int r_inner;
out int r_do;
out int r_early;

int first_multiple(int x, int m) {  // a return inside a loop, inlined
  for (int i = 1; i <= 12; ++i)
    if ((x * i) % m == 0) return i;
  return -1;
}

void main() {
  int sum = 0;
  for (int i = 0; i < n; ++i) {
    if (i == k) break;
    if ((i & 1) == 1) continue;
    sum += i * i + 1;
  }
  r_loop = sum;

  // v is defined in the loop and read after it; lanes leave at different iterations.
  int j = 0;
  int v;
  while (true) {
    v = j * 7 + n * 100;
    if (j >= n) break;
    j += 1 + (k & 1);
  }
  r_last = v;

  if (n > 2) {
    if (k > 3) r_nested = 1;
    else if (k == 3) r_nested = 2;
    else r_nested = 3;
  } else {
    if (s < 0) {
      r_nested = 4;
    } else {
      if (s == n) r_nested = 5;
      else r_nested = 6;
    }
  }

  int w = 0;
  switch (s) {
    case 0: w += 1;
    case 1: w += 10; break;
    case 2: w += 100;
    case 5: w += 1000;
    default: w += 10000; break;
    case -1: w = -1; break;
    case 3: { if (n > 3) break; w += 7; }
    case 4: w += 20;
  }
  r_switch = w;

  r_func = first_multiple(n + 1, k + 2);

  int total = 0;
  for (int a = 0; a < n; ++a)
    for (int b = a; b < k + a; ++b) {
      if (b - a == 3) break;
      total += b;
    }
  r_inner = total;

  int d = n;
  int steps = 0;
  do {
    d = (d & 1) == 0 ? d / 2 : 3 * d + 1;
    ++steps;
  } while (d > 1 && steps < 30);
  r_do = steps * 1000 + d;

  r_early = 1;
  if (n < 0) return;
  r_early = 2;
  if (n > 5) {
    r_early = 3;
    return;
  }
  r_early = 4;
}
)";

struct ControlFlowInputs {
  std::int32_t n, k, s;
};
ControlFlowInputs control_flow_inputs(int index) {
  return {index % 9 - 1, (index * 5) % 7, (index * 4 + index / 9) % 10 - 2};
}

// The kernel above, in C++.
std::array<std::int32_t, 8> control_flow_reference(ControlFlowInputs in) {
  const int n = in.n, k = in.k, s = in.s;
  std::array<std::int32_t, 8> r{};
  int sum = 0;
  for (int i = 0; i < n; ++i) {
    if (i == k) break;
    if ((i & 1) == 1) continue;
    sum += i * i + 1;
  }
  r[0] = sum;
  int j = 0, v = 0;
  while (true) {
    v = j * 7 + n * 100;
    if (j >= n) break;
    j += 1 + (k & 1);
  }
  r[1] = v;
  if (n > 2) r[2] = k > 3 ? 1 : k == 3 ? 2 : 3;
  else r[2] = s < 0 ? 4 : s == n ? 5 : 6;
  int w = 0;
  switch (s) {
    case 0: w += 1; [[fallthrough]];
    case 1: w += 10; break;
    case 2: w += 100; [[fallthrough]];
    case 5: w += 1000; [[fallthrough]];
    default: w += 10000; break;
    case -1: w = -1; break;
    case 3: {
      if (n > 3) break;
      w += 7;
    }
      [[fallthrough]];
    case 4: w += 20;
  }
  r[3] = w;
  r[4] = -1;
  for (int i = 1; i <= 12; ++i)
    if (((n + 1) * i) % (k + 2) == 0) {
      r[4] = i;
      break;
    }
  int total = 0;
  for (int a = 0; a < n; ++a)
    for (int b = a; b < k + a; ++b) {
      if (b - a == 3) break;
      total += b;
    }
  r[5] = total;
  int d = n, steps = 0;
  do {
    d = (d & 1) == 0 ? d / 2 : 3 * d + 1;
    ++steps;
  } while (d > 1 && steps < 30);
  r[6] = steps * 1000 + d;
  r[7] = n < 0 ? 1 : n > 5 ? 3 : 4;
  return r;
}

const std::vector<std::string> kControlFlowOutputs = {"r_loop", "r_inner", "r_last", "r_nested", "r_switch",
                                                      "r_func", "r_do", "r_early"};

TEST(Executor, DivergentControlFlowGivesEachLaneItsOwnResult) {
  Kernel k(kControlFlow);
  const int n = 64;
  k.begin(n);
  for (int l = 0; l < n; ++l) {
    const ControlFlowInputs in = control_flow_inputs(l);
    k.set_i32("n", l, 0, in.n);
    k.set_i32("k", l, 0, in.k);
    k.set_i32("s", l, 0, in.s);
  }
  k.run();
  for (int l = 0; l < n; ++l) {
    const ControlFlowInputs in = control_flow_inputs(l);
    const auto want = control_flow_reference(in);
    SCOPED_TRACE("lane " + std::to_string(l) + ": n = " + std::to_string(in.n) + ", k = " + std::to_string(in.k) +
                 ", s = " + std::to_string(in.s));
    EXPECT_EQ(k.i32("r_loop", l), want[0]) << "loop with break and continue";
    EXPECT_EQ(k.i32("r_last", l), want[1]) << "value defined in the loop, read after it";
    EXPECT_EQ(k.i32("r_nested", l), want[2]) << "nested ifs";
    EXPECT_EQ(k.i32("r_switch", l), want[3]) << "switch with fallthrough";
    EXPECT_EQ(k.i32("r_func", l), want[4]) << "return inside a loop of an inlined function";
    EXPECT_EQ(k.i32("r_inner", l), want[5]) << "nested loops";
    EXPECT_EQ(k.i32("r_do", l), want[6]) << "do-while";
    EXPECT_EQ(k.i32("r_early", l), want[7]) << "early return from main";
  }
  // A few spelled out: lane 0 has n = -1 (no iteration, early return), lane 8 has n = 7.
  EXPECT_EQ(k.i32("r_last", 0), -100);
  EXPECT_EQ(k.i32("r_early", 0), 1);
  EXPECT_EQ(k.i32("r_early", 8), 3);
  EXPECT_EQ(k.i32("r_switch", 3), 11);     // s = 0: case 0 falls into case 1
  EXPECT_EQ(k.i32("r_switch", 1), 11100);  // s = 2: case 2 falls into case 5, then default
  EXPECT_EQ(k.i32("r_switch", 4), 20);     // s = 4
}

TEST(Executor, DivergentLoopsPreserveValuesOfLanesThatLeftEarly) {
  // Each lane leaves after `n` iterations; x is computed in the loop body before the exit test,
  // so after the loop every lane must see the x of its own last iteration, not a later lane's.
  Kernel k(R"(#version 450
layout(location = 0) in int n;
out int r_x;
out float r_f;
void main() {
  int i = 0;
  int x;
  float f = 1.0;
  for (;;) {
    x = i * i + 3;
    f = f * 1.5;
    if (i == n) break;
    ++i;
  }
  r_x = x;
  r_f = f;
}
)");
  const int lanes = 64;
  k.begin(lanes);
  for (int l = 0; l < lanes; ++l) k.set_i32("n", l, 0, (l * 37) % 64);
  k.run();
  for (int l = 0; l < lanes; ++l) {
    const int n = (l * 37) % 64;
    float f = 1.0f;
    for (int i = 0; i <= n; ++i) f = f * 1.5f;
    EXPECT_EQ(k.i32("r_x", l), n * n + 3) << "lane " << l;
    EXPECT_EQ(bits(k.f32("r_f", l)), bits(f)) << "lane " << l;
  }
}

TEST(Executor, GlobalsAndLocalsStartFromTheirInitializersInEveryBatch) {
  Kernel k(R"(#version 450
layout(location = 0) in int n;
out int r_counter;
out float r_table;
out int r_sum;
int counter = 3;
float table[4] = float[4](1.0, 2.0, 4.0, 8.0);
void bump() { counter += 2; }
void main() {
  for (int i = 0; i < n; ++i) bump();
  table[n & 3] += 0.5;
  r_counter = counter;
  r_table = table[(n + 1) & 3] + table[n & 3];
  int local[3];
  for (int i = 0; i < 3; ++i) local[i] = i * n;
  local[n % 3] = 100;
  r_sum = local[0] + local[1] + local[2];
}
)");
  auto set = [](Kernel& kk, int lane, int index) { kk.set_i32("n", lane, 0, index % 7); };
  const std::vector<std::string> outs = {"r_counter", "r_table", "r_sum"};
  for (int batch : {64, 5, 1}) {
    const auto got = k.run_batches(20, batch, set, outs);
    for (int i = 0; i < 20; ++i) {
      const int n = i % 7;
      float table[4] = {1.0f, 2.0f, 4.0f, 8.0f};
      table[n & 3] += 0.5f;
      int local[3] = {0, n, 2 * n};
      local[n % 3] = 100;
      EXPECT_EQ(got[std::size_t(i)], (std::vector<std::uint32_t>{std::uint32_t(3 + 2 * n),
                                                                   bits(table[(n + 1) & 3] + table[n & 3]),
                                                                   std::uint32_t(local[0] + local[1] + local[2])}))
          << "invocation " << i << " in batches of " << batch;
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Dynamic indexing: out-of-range indices are clamped into the array (robust access).

TEST(Executor, DynamicIndexingClampsIntoArraysVectorsAndMatrices) {
  Kernel k(R"(#version 450
layout(location = 0) in ivec2 ij;
layout(location = 1) in uint u;
layout(location = 2) in float base;
struct S {
  int a;
  vec2 b;
  float c[3];
};
uniform float ua[4];
out float r_arr;
out float r_arr_u;
out float r_vec;
out vec3 r_col;
out float r_elem;
out float r_uni;
out float r_w[4];
out vec4 r_vw;
out int r_sa;
out float r_sb;
out float r_sc;
void main() {
  int i = ij.x, j = ij.y;
  float arr[5] = float[5](base, base + 1.0, base + 2.0, base + 3.0, base + 4.0);
  r_arr = arr[i];
  r_arr_u = arr[u];
  vec4 v = vec4(base, base * 2.0, base * 3.0, base * 4.0);
  r_vec = v[i];
  mat3 m = mat3(base, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0);
  r_col = m[i];
  r_elem = m[i][j];
  r_uni = ua[i];
  float w[4] = float[4](0.0, 0.0, 0.0, 0.0);
  w[i] = base;
  r_w = w;
  vec4 vw = vec4(0.0);
  vw[j] = base;
  r_vw = vw;
  S s[3];
  for (int q = 0; q < 3; ++q) {
    s[q].a = q * 10;
    s[q].b = vec2(float(q), base);
    s[q].c = float[3](float(q), float(q) + 0.5, base);
  }
  r_sa = s[i].a;
  r_sb = s[j].b[i];
  r_sc = s[i].c[j];
}
)");
  struct Case {
    std::int32_t i, j;
    std::uint32_t u;
  };
  const std::vector<Case> cases = {
      {0, 0, 0u},        {1, 2, 1u},          {2, 1, 2u},           {3, 3, 3u},
      {4, 0, 4u},        {-1, -1, 5u},        {5, 4, 0xffffffffu},  {100, 7, 0x80000000u},
      {kIntMin, kIntMax, 7u}, {kIntMax, kIntMin, 2u}, {2, -5, 0u},  {-3, 2, 1u}};
  const int n = int(cases.size());
  const float ua[4] = {0.5f, 1.5f, 2.5f, 3.5f};
  k.begin(n);
  for (int q = 0; q < 4; ++q) k.set_f32("ua", 0, std::uint32_t(q), ua[q]);
  for (int l = 0; l < n; ++l) {
    k.set_i32("ij", l, 0, cases[l].i);
    k.set_i32("ij", l, 1, cases[l].j);
    k.set("u", l, 0, cases[l].u);
    k.set_f32("base", l, 0, 10.0f * float(l + 1));
  }
  k.run();
  auto clamp = [](std::int64_t x, int len) { return int(std::clamp<std::int64_t>(x, 0, len - 1)); };
  for (int l = 0; l < n; ++l) {
    const Case& c = cases[l];
    const float base = 10.0f * float(l + 1);
    SCOPED_TRACE("lane " + std::to_string(l) + ": i = " + std::to_string(c.i) + ", j = " + std::to_string(c.j) +
                 ", u = " + std::to_string(c.u));
    const int i5 = clamp(c.i, 5), i4 = clamp(c.i, 4), i3 = clamp(c.i, 3), j3 = clamp(c.j, 3), j4 = clamp(c.j, 4);
    const int u5 = clamp(std::int64_t(c.u), 5);  // an unsigned index: 0xffffffff is past the end
    EXPECT_EQ(k.f32("r_arr", l), base + float(i5));
    EXPECT_EQ(k.f32("r_arr_u", l), base + float(u5));
    EXPECT_EQ(k.f32("r_vec", l), base * float(i4 + 1));
    const float m[3][3] = {{base, 1.0f, 2.0f}, {3.0f, 4.0f, 5.0f}, {6.0f, 7.0f, 8.0f}};
    for (int r = 0; r < 3; ++r) EXPECT_EQ(k.f32("r_col", l, std::uint32_t(r)), m[i3][r]) << "row " << r;
    EXPECT_EQ(k.f32("r_elem", l), m[i3][j3]);
    EXPECT_EQ(k.f32("r_uni", l), ua[i4]);
    for (int q = 0; q < 4; ++q) {
      EXPECT_EQ(k.f32("r_w", l, std::uint32_t(q)), q == i4 ? base : 0.0f) << "write w[" << q << "]";
      EXPECT_EQ(k.f32("r_vw", l, std::uint32_t(q)), q == j4 ? base : 0.0f) << "write vw[" << q << "]";
    }
    EXPECT_EQ(k.i32("r_sa", l), i3 * 10);
    EXPECT_EQ(k.f32("r_sb", l), clamp(c.i, 2) == 0 ? float(j3) : base);
    const float sc[3] = {float(i3), float(i3) + 0.5f, base};
    EXPECT_EQ(k.f32("r_sc", l), sc[j3]);
  }
}

// ---------------------------------------------------------------------------------------------
// Doubles

const char* kDoubles = R"(#version 450
layout(location = 0) in dvec2 d;
layout(location = 1) in double e;
layout(location = 2) in float f;
layout(location = 3) in uvec2 w;
layout(location = 4) in int di;
out double rd[12];
out dvec2 rv;
out dmat2 rm;
out dvec2 rmv;
out dmat2 rinv;
out float rf;
out int ri;
out uvec2 rw;
out double rdyn;
out dvec3 rins;
out double racc;
out double rarr;
void main() {
  rd[0] = d.x + e;
  rd[1] = d.x * d.y - e;
  rd[2] = d.y / e;
  rd[3] = sqrt(abs(e));
  rd[4] = fma(d.x, d.y, e);
  rd[5] = floor(e) * 4.0lf + fract(e);
  rd[6] = double(f);
  rd[7] = packDouble2x32(w);
  rd[8] = min(d.x, e) + max(d.y, e) * 2.0lf;
  rd[9] = clamp(e, -1.0lf, 1.0lf) + mix(d.x, d.y, 0.25lf);
  dmat2 m = dmat2(d, d.yx * e);
  rd[10] = determinant(m);
  rd[11] = dot(d, d.yx) + length(d);
  rv = d * e + dvec2(1.0lf, 2.0lf);
  rm = m * transpose(m);
  rmv = m * d;
  rinv = inverse(m);
  rf = float(e);
  ri = int(e * 1000.0lf);
  rw = unpackDouble2x32(e);
  dvec3 t3 = dvec3(d, e);
  rdyn = t3[di];          // clamped
  dvec3 z3 = dvec3(0.0lf);
  z3[di] = e;
  rins = z3;
  double acc = 0.0lf;     // a loop of 1 to 6 iterations: lanes leave at different times
  for (int i = 0; i < di + 2; ++i) acc = acc * 0.5lf + e;
  racc = acc;
  double arr[4] = double[4](e, d.y, d.x, e * 3.0lf);
  arr[(di + 1) & 3] = -1.0lf;
  rarr = arr[di];
}
)";

struct DoubleInputs {
  double dx, dy, e;
  float f;
  std::uint32_t wx, wy;
  std::int32_t di;
};
DoubleInputs double_inputs(int index) {
  const double e = (index % 5 == 0 ? -1.0 : 1.0) * (0.1 + 1.0 / double(index + 3));
  return {1.0 / 3.0 + index, -2.5 + 0.125 * index, e, 0.1f * float(index), 0x9999999au + std::uint32_t(index),
          0x3fb99999u, index % 6 - 1};
}

// The kernel's expected words, in its order.
std::vector<std::uint32_t> double_reference(const DoubleInputs& in) {
  const double dx = in.dx, dy = in.dy, e = in.e;
  std::vector<std::uint32_t> out;
  auto put = [&](double v) {
    out.push_back(std::uint32_t(bits(v)));
    out.push_back(std::uint32_t(bits(v) >> 32));
  };
  put(dx + e);
  put(dx * dy - e);
  put(dy / e);
  put(std::sqrt(std::fabs(e)));
  put(std::fma(dx, dy, e));
  put(std::floor(e) * 4.0 + (e - std::floor(e)));
  put(double(in.f));
  put(as_double(in.wx, in.wy));
  put((e < dx ? e : dx) + (dy < e ? e : dy) * 2.0);  // min(x, y) = y < x ? y : x; max(x, y) = x < y ? y : x
  const double t = std::min(std::max(e, -1.0), 1.0);
  put(t + (dx * (1.0 - 0.25) + dy * 0.25));
  // m = columns (dx, dy), (dy * e, dx * e)
  const double m00 = dx, m01 = dy, m10 = dy * e, m11 = dx * e;
  put(m00 * m11 - m10 * m01);
  put((dx * dy + dy * dx) + std::sqrt(dx * dx + dy * dy));
  put(dx * e + 1.0);
  put(dy * e + 2.0);
  // m * transpose(m): t = columns (m00, m10), (m01, m11); entry (c, r) = m(0, r) t(c, 0) + m(1, r) t(c, 1)
  const double tm[2][2] = {{m00, m10}, {m01, m11}};
  const double mm[2][2] = {{m00, m01}, {m10, m11}};
  for (int c = 0; c < 2; ++c)
    for (int r = 0; r < 2; ++r) put(mm[0][r] * tm[c][0] + mm[1][r] * tm[c][1]);
  put(m00 * dx + m10 * dy);
  put(m01 * dx + m11 * dy);
  const double det = m00 * m11 - m10 * m01;
  put(m11 / det);
  put(-m01 / det);
  put(-m10 / det);
  put(m00 / det);
  out.push_back(bits(float(e)));
  const double big = e * 1000.0;
  out.push_back(std::uint32_t(std::int32_t(big)));
  out.push_back(std::uint32_t(bits(e)));
  out.push_back(std::uint32_t(bits(e) >> 32));
  const int c3 = std::clamp(in.di, 0, 2);
  const double t3[3] = {dx, dy, e};
  put(t3[c3]);
  for (int i = 0; i < 3; ++i) put(i == c3 ? e : 0.0);
  double acc = 0.0;
  for (int i = 0; i < in.di + 2; ++i) acc = acc * 0.5 + e;
  put(acc);
  double arr[4] = {e, dy, dx, e * 3.0};
  arr[(in.di + 1) & 3] = -1.0;
  put(arr[std::clamp(in.di, 0, 3)]);
  return out;
}
const std::vector<std::string> kDoubleOutputs = {"rd",   "rv", "rm",   "rmv",  "rinv", "rf",
                                                 "ri",   "rw", "rdyn", "rins", "racc", "rarr"};

void set_double_inputs(Kernel& k, int lane, int index) {
  const DoubleInputs in = double_inputs(index);
  k.set_f64("d", lane, 0, in.dx);
  k.set_f64("d", lane, 2, in.dy);
  k.set_f64("e", lane, 0, in.e);
  k.set_f32("f", lane, 0, in.f);
  k.set("w", lane, 0, in.wx);
  k.set("w", lane, 1, in.wy);
  k.set_i32("di", lane, 0, in.di);
}

void expect_double_results(const std::vector<std::vector<std::uint32_t>>& got) {
  for (std::size_t i = 0; i < got.size(); ++i) {
    const std::vector<std::uint32_t> want = double_reference(double_inputs(int(i)));
    ASSERT_EQ(got[i].size(), want.size());
    const auto diff = std::mismatch(want.begin(), want.end(), got[i].begin());
    if (diff.first != want.end())
      ADD_FAILURE() << "invocation " << i << ": first difference at word " << (diff.first - want.begin())
                    << ": want 0x" << std::hex << *diff.first << ", got 0x" << *diff.second;
  }
}

TEST(Executor, DoublesInAFullBatch) {
  // 64 lanes in step (DoublesInPartialBatches: batches of 1 and 7).
  Kernel k(kDoubles);
  expect_double_results(k.run_batches(64, 64, set_double_inputs, kDoubleOutputs));
}

// A double's lanes are interleaved over two rows: copies under a partial mask or in a batch of
// fewer than 64 lanes move whole doubles (dvec2(a, b) with one lane is (a, b)).
TEST(Executor, DoublesInPartialBatches) {
  Kernel k(kDoubles);
  for (int batch : {1, 7}) {
    SCOPED_TRACE("batches of " + std::to_string(batch));
    expect_double_results(k.run_batches(64, batch, set_double_inputs, kDoubleOutputs));
  }
}

// A select of a whole double picks each lane's double by that lane's condition.
TEST(Executor, DoubleSelectFollowsEachLanesCondition) {
  Kernel k(R"(#version 450
layout(location = 0) in double a;
layout(location = 1) in double b;
layout(location = 2) in int c;
out double r;
void main() { r = c > 0 ? a : b; }
)");
  k.begin(64);
  for (int l = 0; l < 64; ++l) {
    k.set_f64("a", l, 0, 1.5 + l);
    k.set_f64("b", l, 0, -3.25 - l);
    k.set_i32("c", l, 0, l % 3 == 0 ? 1 : 0);
  }
  k.run();
  for (int l = 0; l < 64; ++l) EXPECT_EQ(k.f64("r", l), l % 3 == 0 ? 1.5 + l : -3.25 - l) << "lane " << l;
}

// ---------------------------------------------------------------------------------------------
// Matrices: products sum in index order (executor.cpp, Runner::matrix), but for mat4 * vec4.

struct Mat {
  int cols, rows;
  std::vector<float> v;  // column-major
  float operator()(int c, int r) const { return v[std::size_t(c * rows + r)]; }
};

Mat mat_mul(const Mat& a, const Mat& b) {
  Mat out{b.cols, a.rows, std::vector<float>(std::size_t(b.cols * a.rows))};
  for (int j = 0; j < b.cols; ++j)
    for (int r = 0; r < a.rows; ++r) {
      float s = a(0, r) * b(j, 0);
      for (int c = 1; c < a.cols; ++c) s = s + a(c, r) * b(j, c);
      out.v[std::size_t(j * a.rows + r)] = s;
    }
  return out;
}

TEST(Executor, MatrixProductsSumInIndexOrder) {
  Kernel k(R"(#version 450
layout(location = 0) in mat4 m;
layout(location = 4) in mat4 n;
layout(location = 8) in vec4 v;
out vec3 r_m3v;
out vec3 r_vm3;
out mat4 r_mm;
out mat3 r_mm3;
out mat4 r_t;
out mat4 r_outer;
out vec2 r_m32v;
out mat3 r_m23m32;
out mat2x3 r_outer23;
out vec4 r_scaled;
void main() {
  r_m3v = mat3(m) * v.xyz;
  r_vm3 = v.xyz * mat3(m);
  r_mm = m * n;
  r_mm3 = mat3(m) * mat3(n);
  r_t = transpose(m);
  r_outer = outerProduct(v, v.wzyx);
  r_m32v = mat3x2(m) * v.xyz;
  r_m23m32 = mat2x3(m) * mat3x2(n);
  r_outer23 = outerProduct(v.xyz, v.zw);
  r_scaled = (m * 0.75)[2];
}
)");
  const int lanes = 8;
  std::vector<Mat> ms, ns;
  std::vector<std::array<float, 4>> vs;
  for (int l = 0; l < lanes; ++l) {
    Mat a{4, 4, {}}, b{4, 4, {}};
    for (int i = 0; i < 16; ++i) {
      a.v.push_back(float((i * 7 + l * 3) % 11) * 0.1f - 0.35f + float(l) * 1e-3f);
      b.v.push_back(1.0f / float(i + l + 1) - float(i % 3) * 0.3f);
    }
    ms.push_back(a);
    ns.push_back(b);
    vs.push_back({0.3f + float(l), -1.7f, 2.9f / float(l + 1), 0.01f * float(l)});
  }
  k.begin(lanes);
  for (int l = 0; l < lanes; ++l) {
    for (int i = 0; i < 16; ++i) {
      k.set_f32("m", l, std::uint32_t(i), ms[l].v[std::size_t(i)]);
      k.set_f32("n", l, std::uint32_t(i), ns[l].v[std::size_t(i)]);
    }
    for (int i = 0; i < 4; ++i) k.set_f32("v", l, std::uint32_t(i), vs[l][std::size_t(i)]);
  }
  k.run();
  auto sub = [](const Mat& a, int cols, int rows) {
    Mat out{cols, rows, {}};
    for (int c = 0; c < cols; ++c)
      for (int r = 0; r < rows; ++r) out.v.push_back(a(c, r));
    return out;
  };
  auto vec = [](std::initializer_list<float> x) { return Mat{1, int(x.size()), std::vector<float>(x)}; };
  auto row = [](std::initializer_list<float> x) { return Mat{int(x.size()), 1, std::vector<float>(x)}; };
  auto expect = [&](const char* name, int lane, const Mat& want) {
    for (std::size_t i = 0; i < want.v.size(); ++i)
      EXPECT_EQ(bits(k.f32(name, lane, std::uint32_t(i))), bits(want.v[i]))
          << name << " lane " << lane << " word " << i << ": " << want.v[i] << " vs " << k.f32(name, lane, std::uint32_t(i));
  };
  for (int l = 0; l < lanes; ++l) {
    const Mat& m = ms[l];
    const Mat& n = ns[l];
    const auto& v = vs[l];
    expect("r_m3v", l, mat_mul(sub(m, 3, 3), vec({v[0], v[1], v[2]})));
    expect("r_vm3", l, mat_mul(row({v[0], v[1], v[2]}), sub(m, 3, 3)));
    expect("r_mm", l, mat_mul(m, n));
    expect("r_mm3", l, mat_mul(sub(m, 3, 3), sub(n, 3, 3)));
    Mat t{4, 4, {}};
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) t.v.push_back(m(r, c));
    expect("r_t", l, t);
    expect("r_outer", l, mat_mul(vec({v[0], v[1], v[2], v[3]}), row({v[3], v[2], v[1], v[0]})));
    expect("r_m32v", l, mat_mul(sub(m, 3, 2), vec({v[0], v[1], v[2]})));
    expect("r_m23m32", l, mat_mul(sub(m, 2, 3), sub(n, 3, 2)));
    expect("r_outer23", l, mat_mul(vec({v[0], v[1], v[2]}), row({v[2], v[3]})));
    expect("r_scaled", l, vec({m(2, 0) * 0.75f, m(2, 1) * 0.75f, m(2, 2) * 0.75f, m(2, 3) * 0.75f}));
  }
}

TEST(Executor, MatrixTimesVectorOfEveryShapeWithExactValues) {
  // Small integers: every order of summation gives the same (exact) values, so this pins the
  // arithmetic, not the order (see Mat4TimesVec4SumsAsGlm for mat4 * vec4's order).
  Kernel k(R"(#version 450
layout(location = 0) in mat4 m;
layout(location = 4) in vec4 v;
out vec4 r_mv;
out vec4 r_vm;
out vec2 r_m2v;
void main() {
  r_mv = m * v;
  r_vm = v * m;
  r_m2v = mat2(m) * v.xy;
}
)");
  k.begin(2);
  for (int l = 0; l < 2; ++l) {
    for (int i = 0; i < 16; ++i) k.set_f32("m", l, std::uint32_t(i), float(i + 1 + l));
    for (int i = 0; i < 4; ++i) k.set_f32("v", l, std::uint32_t(i), float(i * 2 - 3 + l));
  }
  k.run();
  for (int l = 0; l < 2; ++l) {
    auto m = [&](int c, int r) { return double(c * 4 + r + 1 + l); };
    auto v = [&](int i) { return double(i * 2 - 3 + l); };
    for (int r = 0; r < 4; ++r) {
      EXPECT_EQ(double(k.f32("r_mv", l, std::uint32_t(r))), m(0, r) * v(0) + m(1, r) * v(1) + m(2, r) * v(2) + m(3, r) * v(3));
      EXPECT_EQ(double(k.f32("r_vm", l, std::uint32_t(r))), m(r, 0) * v(0) + m(r, 1) * v(1) + m(r, 2) * v(2) + m(r, 3) * v(3));
    }
    for (int r = 0; r < 2; ++r)
      EXPECT_EQ(double(k.f32("r_m2v", l, std::uint32_t(r))), m(0, r) * v(0) + m(1, r) * v(1));
  }
}

// mat4 * vec4 sums as glm 0.9.9.8 does (detail/type_mat4x4.inl), in pairs:
// (m[0] v.x + m[1] v.y) + (m[2] v.z + m[3] v.w), so that the built-in programs (glm) and their
// GLSL twins agree to the bit; every other product sums in index order, as glm's do.
TEST(Executor, Mat4TimesVec4SumsAsGlm) {
  Kernel k(R"(#version 450
layout(location = 0) in mat4 m;
layout(location = 4) in vec4 v;
layout(location = 5) in dmat4 dm;
layout(location = 13) in dvec4 dv;
out vec4 r;
out dvec4 rd;
void main() {
  r = m * v;
  rd = dm * dv;
}
)");
  const float m[16] = {0.1f, 0.7f, -0.3f, 1.1f, 1e8f, 0.2f, 0.9f, -0.6f, -1e8f, 0.3f, 0.45f, 0.05f, 0.5f, 1.3f, -0.2f, 0.8f};
  const float v[4] = {1.0f, 1.0f, 1.0f, 0.3f};
  double dm[16], dv[4];
  for (int i = 0; i < 16; ++i) dm[i] = double(m[i]) * (i == 4 || i == 8 ? 1e9 : 1.0);
  for (int i = 0; i < 4; ++i) dv[i] = double(v[i]);
  k.begin(1);
  for (int i = 0; i < 16; ++i) {
    k.set_f32("m", 0, std::uint32_t(i), m[i]);
    k.set_f64("dm", 0, std::uint32_t(2 * i), dm[i]);
  }
  for (int i = 0; i < 4; ++i) {
    k.set_f32("v", 0, std::uint32_t(i), v[i]);
    k.set_f64("dv", 0, std::uint32_t(2 * i), dv[i]);
  }
  k.run();
  const glm::vec4 want = glm::make_mat4(m) * glm::make_vec4(v);
  const glm::dvec4 want_d = glm::make_mat4(dm) * glm::make_vec4(dv);
  for (int r = 0; r < 4; ++r) {
    EXPECT_EQ(bits(k.f32("r", 0, std::uint32_t(r))), bits(want[r])) << "row " << r;
    EXPECT_EQ(bits(k.f64("rd", 0, std::uint32_t(2 * r))), bits(want_d[r])) << "dmat4 row " << r;
  }
  // For row 0, glm's pairs give (0.1 + 1e8) + (-1e8 + 0.15) = 0; index order gives 0.15.
  EXPECT_EQ(want[0], 0.0f);
  EXPECT_EQ(want_d[0], 0.0);
}

// Cofactor expansion in 64-bit integers, for exact expected inverses and determinants.
std::int64_t int_det(const std::vector<std::int64_t>& a, int n) {
  if (n == 1) return a[0];
  std::int64_t det = 0;
  for (int c = 0; c < n; ++c) {
    std::vector<std::int64_t> minor;
    for (int cc = 0; cc < n; ++cc)
      for (int r = 1; r < n; ++r)
        if (cc != c) minor.push_back(a[std::size_t(cc * n + r)]);
    const std::int64_t term = a[std::size_t(c * n)] * int_det(minor, n - 1);
    det += (c & 1) ? -term : term;
  }
  return det;
}
std::int64_t int_cofactor(const std::vector<std::int64_t>& a, int n, int col, int row) {
  std::vector<std::int64_t> minor;
  for (int c = 0; c < n; ++c)
    for (int r = 0; r < n; ++r)
      if (c != col && r != row) minor.push_back(a[std::size_t(c * n + r)]);
  const std::int64_t d = n == 1 ? 1 : int_det(minor, n - 1);
  return ((col + row) & 1) ? -d : d;
}

TEST(Executor, DeterminantAndInverseOfIntegerMatrices) {
  Kernel k(R"(#version 450
layout(location = 0) in mat4 m;
out float r_det2;
out float r_det3;
out float r_det4;
out mat2 r_inv2;
out mat3 r_inv3;
out mat4 r_inv4;
void main() {
  r_det2 = determinant(mat2(m));
  r_det3 = determinant(mat3(m));
  r_det4 = determinant(m);
  r_inv2 = inverse(mat2(m));
  r_inv3 = inverse(mat3(m));
  r_inv4 = inverse(m);
}
)");
  // Unit triangular factors give determinants of +-1, +-2, +-4, so that every inverse is exact.
  const std::vector<std::array<std::int64_t, 16>> mats = {
      {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1},
      {2, 1, 0, 3, 1, 1, 2, 0, 0, 1, 1, 1, 1, 0, 2, 1},
      {1, 2, 3, 4, 0, 1, 2, 3, 0, 0, 1, 2, 0, 0, 0, 1},
      {0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 2, 0, 0, 2, 0},
      {4, 3, 0, 1, 1, 1, 1, 2, 2, 0, 1, 3, -1, 2, 2, 1},
      {1, 2, 0, 0, 3, 4, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1},
      {-2, 0, 0, 0, 0, 1, 5, 0, 0, 0, 1, 0, 7, 0, 0, -1},
      {1, 1, 1, 1, 1, 2, 3, 4, 1, 3, 6, 10, 1, 4, 10, 20},
  };
  const int lanes = int(mats.size());
  k.begin(lanes);
  for (int l = 0; l < lanes; ++l)
    for (int i = 0; i < 16; ++i) k.set_f32("m", l, std::uint32_t(i), float(mats[l][std::size_t(i)]));
  k.run();
  for (int l = 0; l < lanes; ++l) {
    SCOPED_TRACE("lane " + std::to_string(l));
    for (int n = 2; n <= 4; ++n) {
      std::vector<std::int64_t> a;
      for (int c = 0; c < n; ++c)
        for (int r = 0; r < n; ++r) a.push_back(mats[l][std::size_t(c * 4 + r)]);
      const std::int64_t det = int_det(a, n);
      const std::string suffix = std::to_string(n);
      EXPECT_EQ(k.f32("r_det" + suffix, l), float(det)) << "determinant of mat" << n;
      const std::int64_t mag = det < 0 ? -det : det;
      if (mag == 0 || (mag & (mag - 1)) != 0) continue;  // the inverse is exact for +-2^k only
      for (int c = 0; c < n; ++c)
        for (int r = 0; r < n; ++r) {
          const double want = double(int_cofactor(a, n, r, c)) / double(det);  // adjugate / det
          EXPECT_EQ(double(k.f32("r_inv" + suffix, l, std::uint32_t(c * n + r))), want)
              << "inverse of mat" << n << " column " << c << " row " << r;
        }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// GLSL.std.450

TEST(Executor, ExtendedInstructionsOnFloats) {
  Kernel k(R"(#version 450
layout(location = 0) in vec4 a;
out float r[42];
void main() {
  float x = a.x, y = a.y, z = a.z;
  r[0] = floor(x);
  r[1] = ceil(x);
  r[2] = trunc(x);
  r[3] = fract(x);
  r[4] = round(x);
  r[5] = roundEven(x);
  r[6] = abs(x);
  r[7] = sign(x);
  r[8] = sqrt(x);
  r[9] = inversesqrt(x);
  r[10] = min(x, y);
  r[11] = max(x, y);
  r[12] = clamp(x, y, z);
  r[13] = mix(x, y, z);
  r[14] = step(y, x);
  r[15] = smoothstep(y, z, x);
  r[16] = fma(x, y, z);
  r[17] = radians(x);
  r[18] = degrees(x);
  r[19] = sin(x);
  r[20] = cos(x);
  r[21] = tan(x);
  r[22] = asin(x);
  r[23] = acos(x);
  r[24] = atan(x);
  r[25] = sinh(x);
  r[26] = cosh(x);
  r[27] = tanh(x);
  r[28] = asinh(x);
  r[29] = acosh(x);
  r[30] = atanh(x);
  r[31] = exp(x);
  r[32] = exp2(x);
  r[33] = log(x);
  r[34] = log2(x);
  r[35] = pow(x, y);
  r[36] = atan(x, y);
  r[37] = ldexp(x, int(a.w));
  r[38] = mod(x, y);
  r[39] = mix(x, y, z > 0.5);
  r[40] = min(y, x);
  r[41] = max(y, x);
}
)");
  const std::vector<std::array<float, 4>> in = {
      {0.5f, 2.0f, 0.25f, 3.0f},      {-0.5f, 0.3f, 0.7f, -2.0f},   {2.5f, -1.25f, 3.0f, 1.0f},
      {-2.5f, 0.0f, 1.0f, 0.0f},      {3.5f, 3.5f, 0.5f, 130.0f},   {-0.0f, 1.0f, 0.0f, 5.0f},
      {1.0f, 0.5f, 2.0f, -130.0f},    {7.3f, -2.0f, 0.1f, 4.0f},    {kNaN, 1.0f, 2.0f, 0.0f},
      {kInf, 2.0f, 1.0f, 1.0f},       {-kInf, -3.0f, 4.0f, 2.0f},   {1e-40f, 2.0f, 0.9f, 10.0f},
      {100.25f, 1.5f, -1.0f, -1.0f},  {-3.75f, kNaN, 0.6f, -200.0f},   {0.99f, 0.5f, 1.0f, 200.0f},
      {1.5f, 1.0f, 2.0f, 0.0f}};
  const int n = int(in.size());
  k.begin(n);
  for (int l = 0; l < n; ++l)
    for (int c = 0; c < 4; ++c) k.set_f32("a", l, std::uint32_t(c), in[l][std::size_t(c)]);
  k.run();
  for (int l = 0; l < n; ++l) {
    const float x = in[l][0], y = in[l][1], z = in[l][2];
    const int ex = int(in[l][3]);
    SCOPED_TRACE("lane " + std::to_string(l) + ": x = " + std::to_string(x) + ", y = " + std::to_string(y) +
                 ", z = " + std::to_string(z));
    auto r = [&](int i) { return k.f32("r", l, std::uint32_t(i)); };
    EXPECT_TRUE(same(std::floor(x), r(0))) << "floor";
    EXPECT_TRUE(same(std::ceil(x), r(1))) << "ceil";
    EXPECT_TRUE(same(std::trunc(x), r(2))) << "trunc";
    EXPECT_TRUE(same(x - std::floor(x), r(3))) << "fract";
    EXPECT_TRUE(same(std::round(x), r(4))) << "round: halves away from zero";
    EXPECT_TRUE(same(std::nearbyint(x), r(5))) << "roundEven";
    EXPECT_TRUE(same(std::fabs(x), r(6))) << "abs";
    const float sgn = x > 0.0f ? 1.0f : x < 0.0f ? -1.0f : x;  // keeps -0.0 and NaN
    EXPECT_TRUE(same(sgn, r(7))) << "sign";
    EXPECT_TRUE(same(std::sqrt(x), r(8))) << "sqrt";
    EXPECT_TRUE(same(1.0f / std::sqrt(x), r(9))) << "inversesqrt";
    EXPECT_TRUE(same(y < x ? y : x, r(10))) << "min: y < x ? y : x";
    EXPECT_TRUE(same(x < y ? y : x, r(11))) << "max: x < y ? y : x";
    const float lo = x < y ? y : x;
    EXPECT_TRUE(same(z < lo ? z : lo, r(12))) << "clamp: min(max(x, y), z)";
    EXPECT_TRUE(same(x * (1.0f - z) + y * z, r(13))) << "mix";
    EXPECT_TRUE(same(x < y ? 0.0f : 1.0f, r(14))) << "step";
    float t = (x - y) / (z - y);
    t = t < 0.0f ? 0.0f : (1.0f < t ? 1.0f : t);
    EXPECT_TRUE(same(t * t * (3.0f - 2.0f * t), r(15))) << "smoothstep";
    EXPECT_TRUE(same(std::fma(x, y, z), r(16))) << "fma";
    EXPECT_TRUE(same(x * 0.017453292519943295f, r(17))) << "radians";
    EXPECT_TRUE(same(x * 57.29577951308232f, r(18))) << "degrees";
    // Transcendentals: tessref's own functions, to the bit (NaN included: 0x7fc00000).
    EXPECT_EQ(bits(r(19)), bits(math::sin(x))) << "sin";
    EXPECT_EQ(bits(r(20)), bits(math::cos(x))) << "cos";
    EXPECT_EQ(bits(r(21)), bits(math::tan(x))) << "tan";
    EXPECT_EQ(bits(r(22)), bits(math::asin(x))) << "asin";
    EXPECT_EQ(bits(r(23)), bits(math::acos(x))) << "acos";
    EXPECT_EQ(bits(r(24)), bits(math::atan(x))) << "atan";
    EXPECT_EQ(bits(r(25)), bits(math::sinh(x))) << "sinh";
    EXPECT_EQ(bits(r(26)), bits(math::cosh(x))) << "cosh";
    EXPECT_EQ(bits(r(27)), bits(math::tanh(x))) << "tanh";
    EXPECT_EQ(bits(r(28)), bits(math::asinh(x))) << "asinh";
    EXPECT_EQ(bits(r(29)), bits(math::acosh(x))) << "acosh";
    EXPECT_EQ(bits(r(30)), bits(math::atanh(x))) << "atanh";
    EXPECT_EQ(bits(r(31)), bits(math::exp(x))) << "exp";
    EXPECT_EQ(bits(r(32)), bits(math::exp2(x))) << "exp2";
    EXPECT_EQ(bits(r(33)), bits(math::log(x))) << "log";
    EXPECT_EQ(bits(r(34)), bits(math::log2(x))) << "log2";
    EXPECT_EQ(bits(r(35)), bits(math::pow(x, y))) << "pow";
    EXPECT_EQ(bits(r(36)), bits(math::atan2(x, y))) << "atan(y, x)";
    EXPECT_TRUE(same(std::ldexp(x, ex), r(37))) << "ldexp";
    EXPECT_TRUE(same(x - y * std::floor(x / y), r(38))) << "mod";
    EXPECT_TRUE(same(z > 0.5f ? y : x, r(39))) << "mix with a bool";
    EXPECT_TRUE(same(x < y ? x : y, r(40))) << "min(y, x)";
    EXPECT_TRUE(same(y < x ? x : y, r(41))) << "max(y, x)";
  }
  // Spelled out.
  EXPECT_EQ(k.f32("r", 2, 4), 3.0f);    // round(2.5)
  EXPECT_EQ(k.f32("r", 2, 5), 2.0f);    // roundEven(2.5)
  EXPECT_EQ(k.f32("r", 3, 5), -2.0f);   // roundEven(-2.5)
  EXPECT_EQ(k.f32("r", 4, 5), 4.0f);    // roundEven(3.5)
  EXPECT_EQ(bits(k.f32("r", 5, 7)), bits(-0.0f));  // sign(-0.0)
  EXPECT_EQ(k.f32("r", 1, 3), 0.5f);    // fract(-0.5)
  EXPECT_EQ(k.f32("r", 11, 37), std::ldexp(1e-40f, 10));  // ldexp of a denormal
  EXPECT_EQ(k.f32("r", 4, 37), kInf);   // ldexp(3.5, 130)
  EXPECT_EQ(k.f32("r", 6, 37), std::ldexp(1.0f, -130));  // a denormal
  EXPECT_EQ(bits(k.f32("r", 13, 37)), 0x80000000u);      // ldexp(-3.75, -200) = -0
  // min(x, y) = y < x ? y : x and max(x, y) = x < y ? y : x: a NaN second operand is ignored,
  // a NaN first operand returned.
  EXPECT_EQ(k.f32("r", 13, 10), -3.75f);                  // min(-3.75, NaN)
  EXPECT_EQ(k.f32("r", 13, 11), -3.75f);                  // max(-3.75, NaN)
  EXPECT_TRUE(std::isnan(k.f32("r", 13, 40)));             // min(NaN, -3.75)
  EXPECT_TRUE(std::isnan(k.f32("r", 13, 41)));             // max(NaN, -3.75)
}

TEST(Executor, ModfSplitsWholeAndFraction) {
  Kernel k(R"(#version 450
layout(location = 0) in float x;
out float r_fract;
out float r_whole;
void main() {
  float whole;
  r_fract = modf(x, whole);
  r_whole = whole;
}
)");
  // Negative whole numbers (whose fraction is -0): ModfFractionOfANegativeWholeNumberIsMinusZero.
  const std::vector<float> in = {2.75f, -2.75f, 0.0f, 3.0f, 1e-40f, -1e-40f, 65536.5f, kInf, -kInf, 0.375f, kNaN};
  const int n = int(in.size());
  k.begin(n);
  for (int l = 0; l < n; ++l) k.set_f32("x", l, 0, in[l]);
  k.run();
  for (int l = 0; l < n; ++l) {
    float whole = 0.0f;
    const float fract = std::modf(in[l], &whole);  // C's modf: modf(+-inf) = +-0, whole +-inf
    EXPECT_TRUE(same(fract, k.f32("r_fract", l))) << in[l];
    EXPECT_TRUE(same(whole, k.f32("r_whole", l))) << in[l];
  }
  EXPECT_EQ(k.f32("r_fract", 1), -0.75f);
  EXPECT_EQ(k.f32("r_whole", 1), -2.0f);
  EXPECT_EQ(bits(k.f32("r_whole", 5)), bits(-0.0f));  // modf(-1e-40): whole -0
  EXPECT_EQ(bits(k.f32("r_fract", 8)), bits(-0.0f));  // modf(-inf)
}

// GLSL 4.60, 8.3: "Both the return value and the output parameter will have the same sign as x."
TEST(Executor, ModfFractionOfANegativeWholeNumberIsMinusZero) {
  Kernel k(R"(#version 450
layout(location = 0) in float x;
out float r_fract;
void main() {
  float whole;
  r_fract = modf(x, whole);
}
)");
  const float in[3] = {-1.0f, -0.0f, -65536.0f};
  k.begin(3);
  for (int l = 0; l < 3; ++l) k.set_f32("x", l, 0, in[l]);
  k.run();
  for (int l = 0; l < 3; ++l) EXPECT_EQ(bits(k.f32("r_fract", l)), bits(-0.0f)) << in[l];
}

// glslang emits frexp as FrexpStruct (a struct result), modf as Modf (a pointer operand).
TEST(Executor, Frexp) {
  Kernel k(R"(#version 450
layout(location = 0) in float x;
out float r_mant;
out int r_exp;
void main() {
  int e;
  r_mant = frexp(x, e);
  r_exp = e;
}
)");
  const std::vector<float> in = {2.75f, -2.75f, 0.0f, -0.0f, 1e-40f, 65536.5f, 0.375f, -1.0f, kInf};
  const int n = int(in.size());
  k.begin(n);
  for (int l = 0; l < n; ++l) k.set_f32("x", l, 0, in[l]);
  k.run();
  for (int l = 0; l < n; ++l) {
    int e = 0;
    const float mant = std::frexp(in[l], &e);
    EXPECT_TRUE(same(mant, k.f32("r_mant", l))) << in[l];
    if (std::isfinite(in[l])) {
      EXPECT_EQ(k.i32("r_exp", l), e) << in[l];
    }
  }
  EXPECT_EQ(k.f32("r_mant", 0), 0.6875f);
  EXPECT_EQ(k.i32("r_exp", 0), 2);
  EXPECT_EQ(k.i32("r_exp", 4), -132);  // 1e-40 is a denormal: 0.5 <= mant < 1 still
}

TEST(Executor, GeometricFunctions) {
  Kernel k(R"(#version 450
layout(location = 0) in vec3 a;
layout(location = 1) in vec3 b;
layout(location = 2) in float eta;
out float r_len;
out float r_dist;
out float r_dot;
out vec3 r_cross;
out vec3 r_norm;
out vec3 r_refl;
out vec3 r_refr;
out vec3 r_ff;
out float r_len2;
void main() {
  r_len = length(a);
  r_dist = distance(a, b);
  r_dot = dot(a, b);
  r_cross = cross(a, b);
  r_norm = normalize(a);
  r_refl = reflect(a, b);
  r_refr = refract(a, b, eta);
  r_ff = faceforward(a, b, -a);
  r_len2 = length(a.xy);
}
)");
  const std::vector<std::array<float, 7>> in = {
      {1.0f, 2.0f, 2.0f, 0.0f, 0.0f, 1.0f, 0.5f},
      {0.3f, -0.7f, 0.1f, 0.6f, 0.8f, 0.0f, 1.33f},
      {-1.5f, 0.25f, 4.0f, 0.0f, 1.0f, 0.0f, 0.9f},
      {0.0f, 0.0f, 0.0f, 1.0f, 1.0f, 1.0f, 1.0f},
      {1e20f, 1e20f, 0.0f, -0.577f, 0.577f, 0.577f, 2.0f},
      {0.6f, -0.8f, 0.0f, 0.0f, 1.0f, 0.0f, 1.5f},
  };
  const int n = int(in.size());
  k.begin(n);
  for (int l = 0; l < n; ++l) {
    for (int c = 0; c < 3; ++c) {
      k.set_f32("a", l, std::uint32_t(c), in[l][std::size_t(c)]);
      k.set_f32("b", l, std::uint32_t(c), in[l][std::size_t(3 + c)]);
    }
    k.set_f32("eta", l, 0, in[l][6]);
  }
  k.run();
  for (int l = 0; l < n; ++l) {
    SCOPED_TRACE("lane " + std::to_string(l));
    const float a[3] = {in[l][0], in[l][1], in[l][2]}, b[3] = {in[l][3], in[l][4], in[l][5]};
    const float eta = in[l][6];
    auto dot = [](const float* p, const float* q) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; };
    EXPECT_TRUE(same(std::sqrt(dot(a, a)), k.f32("r_len", l)));
    const float d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    EXPECT_TRUE(same(std::sqrt(dot(d, d)), k.f32("r_dist", l)));
    EXPECT_TRUE(same(dot(a, b), k.f32("r_dot", l)));
    const float cr[3] = {a[1] * b[2] - b[1] * a[2], a[2] * b[0] - b[2] * a[0], a[0] * b[1] - b[0] * a[1]};
    const float inv = 1.0f / std::sqrt(dot(a, a));
    const float nb = dot(b, a);
    const float kk = 1.0f - eta * eta * (1.0f - nb * nb);
    for (int c = 0; c < 3; ++c) {
      SCOPED_TRACE("component " + std::to_string(c));
      EXPECT_TRUE(same(cr[c], k.f32("r_cross", l, std::uint32_t(c))));
      EXPECT_TRUE(same(a[c] * inv, k.f32("r_norm", l, std::uint32_t(c))));
      EXPECT_TRUE(same(a[c] - b[c] * nb * 2.0f, k.f32("r_refl", l, std::uint32_t(c))));
      EXPECT_TRUE(same(kk < 0.0f ? 0.0f : eta * a[c] - (eta * nb + std::sqrt(kk)) * b[c],
                       k.f32("r_refr", l, std::uint32_t(c))));
      // faceforward(N = a, I = b, Nref = -a): dot(Nref, I) < 0 ? N : -N
      const float nref_dot_i = (-a[0]) * b[0] + (-a[1]) * b[1] + (-a[2]) * b[2];
      EXPECT_TRUE(same(nref_dot_i < 0.0f ? a[c] : -a[c], k.f32("r_ff", l, std::uint32_t(c))));
    }
    EXPECT_TRUE(same(std::sqrt(a[0] * a[0] + a[1] * a[1]), k.f32("r_len2", l)));
  }
  EXPECT_EQ(k.f32("r_len", 0), 3.0f);
  EXPECT_TRUE(std::isnan(k.f32("r_norm", 3, 0)));  // normalize(0): 0 * inf
  EXPECT_EQ(k.f32("r_len", 4), kInf);                // 1e20^2 overflows: no rescaling
}

TEST(Executor, PackingAndUnpacking) {
  Kernel k(R"(#version 450
layout(location = 0) in vec4 f;
layout(location = 1) in uint p;
out uint r_pack[5];
out vec2 r_half;
out vec4 r_unorm8;
out vec4 r_snorm8;
out vec2 r_unorm16;
out vec2 r_snorm16;
void main() {
  r_pack[0] = packHalf2x16(f.xy);
  r_pack[1] = packUnorm4x8(f);
  r_pack[2] = packSnorm4x8(f);
  r_pack[3] = packUnorm2x16(f.zw);
  r_pack[4] = packSnorm2x16(f.zw);
  r_half = unpackHalf2x16(p);
  r_unorm8 = unpackUnorm4x8(p);
  r_snorm8 = unpackSnorm4x8(p);
  r_unorm16 = unpackUnorm2x16(p);
  r_snorm16 = unpackSnorm2x16(p);
}
)");
  const float h = std::ldexp(1.0f, -24);  // the smallest half denormal
  struct Case {
    std::array<float, 4> f;
    std::uint32_t p;
    std::array<std::uint32_t, 5> packs;
  };
  const std::vector<Case> cases = {
      // half(1) = 0x3c00, half(-2) = 0xc000; unorm8: 0.5 * 255 = 127.5 -> 128 (to even).
      {{1.0f, -2.0f, 0.5f, 0.25f}, 0x7c00fc00u, {0xc0003c00u, 0x408000ffu, 0x2040817fu, 0x40008000u, 0x20004000u}},
      // 65520 rounds to infinity; NaN -> 0x7e00 (and a 0 byte when normalized); clamping to [0, 1]
      // and [-1, 1]; -0.5 * 127 = -63.5 -> -64 (to even).
      {{65520.0f, kNaN, -0.5f, 2.0f}, 0x00010000u, {0x7e007c00u, 0xff0000ffu, 0x7fc0007fu, 0xffff0000u, 0x7fffc000u}},
      // 65504 is the largest half; 2^-25 is halfway to 0 (-> 0), 3 * 2^-25 halfway to 2 * 2^-24.
      {{65504.0f, h * 0.5f, -1.0f, 1.0f}, 0x80017bffu, {0x00007bffu, 0xff0000ffu, 0x7f81007fu, 0xffff0000u, 0x7fff8001u}},
      {{h * 1.5f, -kInf, 0.0f, -1.0f}, 0x3c003555u, {0xfc000002u, 0x00000000u, 0x81008100u, 0x00000000u, 0x80010000u}},
      // 1 + 2^-11 is halfway between two halves: to even (0x3c00); 1 + 3 * 2^-11 -> 0x3c02.
      {{1.0f + std::ldexp(1.0f, -11), 1.0f + 3.0f * std::ldexp(1.0f, -11), 0.2f, -0.2f}, 0xffffffffu,
       {0x3c023c00u, 0x0033ffffu, 0xe7197f7fu, 0x00003333u, 0xe6671999u}},
  };
  const int n = int(cases.size());
  k.begin(n);
  for (int l = 0; l < n; ++l) {
    for (int c = 0; c < 4; ++c) k.set_f32("f", l, std::uint32_t(c), cases[l].f[std::size_t(c)]);
    k.set("p", l, 0, cases[l].p);
  }
  k.run();
  auto half = [](std::uint32_t x) {  // IEEE half to float, by its definition
    const int e = int((x >> 10) & 31u), m = int(x & 1023u);
    const float s = (x & 0x8000u) ? -1.0f : 1.0f;
    if (e == 31) return m ? kNaN : s * kInf;
    if (e == 0) return s * std::ldexp(float(m), -24);
    return s * std::ldexp(float(1024 + m), e - 25);
  };
  for (int l = 0; l < n; ++l) {
    SCOPED_TRACE("lane " + std::to_string(l));
    for (int i = 0; i < 5; ++i)
      EXPECT_EQ(k.u32("r_pack", l, std::uint32_t(i)), cases[l].packs[std::size_t(i)])
          << "pack #" << i << " 0x" << std::hex << k.u32("r_pack", l, std::uint32_t(i));
    const std::uint32_t p = cases[l].p;
    for (int c = 0; c < 2; ++c) {
      EXPECT_TRUE(same(half((p >> (16 * c)) & 0xffffu), k.f32("r_half", l, std::uint32_t(c)))) << "half " << c;
      EXPECT_EQ(k.f32("r_unorm16", l, std::uint32_t(c)), float((p >> (16 * c)) & 0xffffu) / 65535.0f);
      const float s16 = float(std::int16_t(std::uint16_t(p >> (16 * c)))) / 32767.0f;
      EXPECT_EQ(k.f32("r_snorm16", l, std::uint32_t(c)), std::max(s16, -1.0f));
    }
    for (int c = 0; c < 4; ++c) {
      EXPECT_EQ(k.f32("r_unorm8", l, std::uint32_t(c)), float((p >> (8 * c)) & 0xffu) / 255.0f);
      const float s8 = float(std::int8_t(std::uint8_t(p >> (8 * c)))) / 127.0f;
      EXPECT_EQ(k.f32("r_snorm8", l, std::uint32_t(c)), std::max(s8, -1.0f));
    }
  }
  // Spelled out: 0xfc00 is -inf, 0x7c00 +inf, 0x0001 the smallest denormal, 0x8001 its negative.
  EXPECT_EQ(k.f32("r_half", 0, 0), -kInf);
  EXPECT_EQ(k.f32("r_half", 0, 1), kInf);
  EXPECT_EQ(k.f32("r_half", 1, 1), h);
  EXPECT_EQ(k.f32("r_half", 2, 1), -h);
  EXPECT_EQ(k.f32("r_half", 2, 0), 65504.0f);
  EXPECT_EQ(k.f32("r_half", 3, 1), 1.0f);
  EXPECT_EQ(k.f32("r_snorm8", 0, 0), 0.0f);
  EXPECT_EQ(k.f32("r_snorm8", 0, 1), -4.0f / 127.0f);  // byte 1 of 0x7c00fc00: 0xfc
  EXPECT_EQ(k.f32("r_snorm8", 2, 0), -1.0f / 127.0f);  // byte 0 of 0x80017bff: 0xff
  EXPECT_EQ(k.f32("r_snorm8", 2, 3), -1.0f);            // byte 3: 0x80 = -128, clamped to -1
  EXPECT_EQ(k.f32("r_unorm8", 3, 0), float(0x55) / 255.0f);  // byte 0 of 0x3c003555
}

// ---------------------------------------------------------------------------------------------
// Batches

TEST(Executor, BatchesOfOneSevenAndSixtyFourLanesAgree) {
  Kernel k(kControlFlow);
  auto set = [](Kernel& kk, int lane, int index) {
    const ControlFlowInputs in = control_flow_inputs(index);
    kk.set_i32("n", lane, 0, in.n);
    kk.set_i32("k", lane, 0, in.k);
    kk.set_i32("s", lane, 0, in.s);
  };
  const int count = 150;
  const auto full = k.run_batches(count, 64, set, kControlFlowOutputs);
  for (int i = 0; i < count; ++i) {
    const auto want = control_flow_reference(control_flow_inputs(i));
    const std::vector<std::uint32_t> w = {std::uint32_t(want[0]), std::uint32_t(want[5]), std::uint32_t(want[1]),
                                          std::uint32_t(want[2]), std::uint32_t(want[3]), std::uint32_t(want[4]),
                                          std::uint32_t(want[6]), std::uint32_t(want[7])};
    EXPECT_EQ(full[std::size_t(i)], w) << "invocation " << i;
  }
  for (int batch : {1, 7, 63}) EXPECT_EQ(k.run_batches(count, batch, set, kControlFlowOutputs), full) << batch;
}

TEST(Executor, BatchesAgreeOnFloatsVectorsAndIndexing) {
  Kernel k(R"(#version 450
layout(location = 0) in vec4 a;
layout(location = 1) in int i;
out vec4 r_v;
out float r_f[3];
out mat2 r_m;
void main() {
  vec4 v = a.wzyx * a.x + vec4(1.0, 2.0, 3.0, 4.0);
  v[i & 3] = length(a);
  float t[3] = float[3](a.x, a.y, a.z);
  for (int q = 0; q < i % 4; ++q) t[q % 3] = t[(q + 1) % 3] * 2.0 + t[q % 3];
  r_v = i > 3 ? v : v.yxwz;
  r_f = t;
  r_m = mat2(a) * mat2(v);
}
)");
  auto set = [](Kernel& kk, int lane, int index) {
    for (int c = 0; c < 4; ++c) kk.set_f32("a", lane, std::uint32_t(c), 0.37f * float(index - 20 + c) + 1.0f / float(c + 2));
    kk.set_i32("i", lane, 0, (index * 13) % 11 - 2);
  };
  const std::vector<std::string> outs = {"r_v", "r_f", "r_m"};
  const auto full = k.run_batches(128, 64, set, outs);
  for (int batch : {1, 7}) EXPECT_EQ(k.run_batches(128, batch, set, outs), full) << batch;
}

// ---------------------------------------------------------------------------------------------
// The instruction budget

const char* kMaybeInfinite = R"(#version 450
layout(location = 0) in int n;
out int r;
void main() {
  int i = 0;
  while (i != n) {
    i += 2;
  }
  r = i;
}
)";

TEST(Executor, InfiniteLoopStopsAtTheInstructionBudget) {
  ExecLimits limits;
  limits.max_instructions = 5000;
  Kernel k(kMaybeInfinite, limits);
  k.begin(4);
  const int n[4] = {0, 40, 7, 2};  // lane 2 never meets its n: i stays even
  for (int l = 0; l < 4; ++l) k.set_i32("n", l, 0, n[l]);
  try {
    k.run();
    FAIL() << "the infinite loop ran to completion";
  } catch (const ShaderRuntimeError& e) {
    EXPECT_EQ(e.lane, 2);
    EXPECT_THAT(e.what(), HasSubstr("instruction budget of 5000 exceeded"));
    EXPECT_THAT(e.what(), HasSubstr("--max-shader-instructions"));
    // The line is that of the block's branch, which legalized SPIR-V may leave without one (0).
    if (e.line != 0) {
      EXPECT_GE(e.line, 6);
      EXPECT_LE(e.line, 8);
    }
  }
}

// docs/executor.md: the budget error names "the stage, patch (or vertex, or pixel), invocation and
// source line", whatever the budget: a block whose branch has no line reports its last statement's.
TEST(Executor, BudgetErrorAlwaysNamesALineOfTheLoop) {
  for (std::uint64_t budget = 5000; budget < 5012; ++budget) {
    ExecLimits limits;
    limits.max_instructions = budget;
    Kernel k(kMaybeInfinite, limits);
    k.begin(1);
    k.set_i32("n", 0, 0, 7);
    try {
      k.run();
      ADD_FAILURE() << "the infinite loop ran to completion";
    } catch (const ShaderRuntimeError& e) {
      EXPECT_GE(e.line, 6) << "budget " << budget;
      EXPECT_LE(e.line, 8) << "budget " << budget;
    }
  }
}

TEST(Executor, TheBudgetIsPerInvocation) {
  // Every lane runs the same long but finite loop: together they run far more than the budget,
  // each one less.
  ExecLimits limits;
  limits.max_instructions = 5000;
  Kernel k(kMaybeInfinite, limits);
  k.begin(64);
  for (int l = 0; l < 64; ++l) k.set_i32("n", l, 0, 200 + 2 * l);  // at most 163 iterations
  EXPECT_NO_THROW(k.run());
  for (int l = 0; l < 64; ++l) EXPECT_EQ(k.i32("r", l), 200 + 2 * l);
  // One lane over the budget stops the batch, naming that lane.
  k.begin(64);
  for (int l = 0; l < 64; ++l) k.set_i32("n", l, 0, l == 37 ? 100000 : 2 * l);
  try {
    k.run();
    FAIL() << "lane 37 ran 50000 iterations within a budget of 5000 instructions";
  } catch (const ShaderRuntimeError& e) {
    EXPECT_EQ(e.lane, 37);
    EXPECT_THAT(e.what(), HasSubstr("instruction budget of 5000 exceeded"));
  }
}

// A vertex shader with a local array of `n` floats that it keeps (indexed by an input).
std::string local_array(const std::string& n, const std::string& index = "[i]") {
  return "#version 450\nlayout(location = 0) in int i;\nlayout(location = 0) out float r;\n"
         "void main() {\n  float big[" + n + "];\n  big" + index + " = 1.0;\n  r = big" + index + ";\n}\n";
}

// The executor keeps kMaxLanes invocations of private memory per thread: a local array of 10^7
// floats took 10 GB. Past ExecLimits::max_private_bytes the program is refused when it is built,
// naming the largest per-invocation variable.
TEST(Executor, PrivateMemoryIsLimitedPerInvocation) {
  ExecLimits limits;
  EXPECT_EQ(limits.max_private_bytes, 1u << 20);
  EXPECT_NO_THROW(Kernel(local_array("100000"), limits));  // 400 KB
  try {
    Kernel k(local_array("300000"), limits);  // 1.2 MB
    FAIL() << "no error";
  } catch (const SpirvError& e) {
    EXPECT_THAT(e.what(), HasSubstr("'big' takes 1200000 bytes per invocation ("));
    EXPECT_THAT(e.what(), HasSubstr("more than the executor's private memory limit of 1048576 bytes per invocation "
                                    "(it keeps 256 invocations per thread)"));
  }
  limits.max_private_bytes = 4096;
  EXPECT_THROW(Kernel(local_array("2000"), limits), SpirvError);
  Kernel small(local_array("100"), limits);
  small.begin(4);
  for (int l = 0; l < 4; ++l) small.set_i32("i", l, 0, 2 * l);
  small.run();
  for (int l = 0; l < 4; ++l) EXPECT_EQ(small.f32("r", l), 1.0f);
}

// One value holds at most kMaxValueWords: the module's flattened layout (an entry per scalar)
// would otherwise take gigabytes before the executor could refuse it; 2^32 words wrapped around.
TEST(Executor, VariablesPastSixteenMiBAreRefusedByName) {
  EXPECT_NO_THROW(read_module(compile_stage(Stage::Vertex, local_array("4194304"))));  // exactly 16 MiB
  for (const auto& [n, bytes] : {std::pair<std::string, std::string>{"4194305", "16777220"},
                                 {"100000000", "400000000"}, {"65536][65536", "17179869184"}}) {
    const std::string index = n.find(']') == std::string::npos ? "[i]" : "[i][i]";
    try {
      read_module(compile_stage(Stage::Vertex, local_array(n, index)));
      FAIL() << n << ": no error";
    } catch (const SpirvError& e) {
      EXPECT_EQ(std::string(e.what()), "'big' is " + bytes + " bytes: one variable holds at most 16 MiB in tessref's "
                                       "executor (GL's minimum GL_MAX_SHADER_STORAGE_BLOCK_SIZE)");
    }
  }
}

// ---------------------------------------------------------------------------------------------
// A fragment shader: discard and derivatives over 2x2 quads

TEST(Executor, FragmentDiscardAndQuadDerivatives) {
  Kernel k(R"(#version 450
layout(location = 0) in float v;
layout(location = 0) out vec4 color;
void main() {
  float dx = dFdx(v);
  float dy = dFdy(v);
  float fw = fwidth(v);
  if (v < 0.0) discard;
  color = vec4(v, dx, dy, fw);
}
)",
           ExecLimits{}, Stage::Fragment);
  const int lanes = 16;  // four quads; lane 4q + k is pixel (k & 1, k >> 1) of quad q
  auto value = [](int l) { return float((l * l) % 13) - (l == 5 || l == 14 ? 20.0f : 0.0f); };
  k.begin(lanes);
  for (int l = 0; l < lanes; ++l) k.set_f32("v", l, 0, value(l));
  k.run();
  for (int l = 0; l < lanes; ++l) {
    SCOPED_TRACE("lane " + std::to_string(l));
    const bool killed = value(l) < 0.0f;
    EXPECT_EQ(k.inv().discarded()[l] != 0, killed);
    if (killed) continue;
    // Fine, as llvmpipe computes every derivative: dFdx within the lane's row, dFdy within its column.
    const int q = l & ~3, row = q + (l & 2), column = q + (l & 1);
    const float dx = value(row + 1) - value(row), dy = value(column + 2) - value(column);
    EXPECT_EQ(k.f32("color", l, 0), value(l));
    EXPECT_EQ(k.f32("color", l, 1), dx);
    EXPECT_EQ(k.f32("color", l, 2), dy);
    EXPECT_EQ(k.f32("color", l, 3), std::fabs(dx) + std::fabs(dy));
  }
}

// A GL_RGBA32F texture of one level with `filter` for minification and magnification.
texture::Texture rgba32f_texture(int width, int height, const std::vector<float>& rgba, texture::Filter filter) {
  texture::Texture t;
  t.levels.push_back(texture::make_level(texture::TexelFormat::kRgba32F, width, height, rgba.data()));
  t.sampler.min_filter = t.sampler.mag_filter = filter;
  t.finalize();
  return t;
}

// ---------------------------------------------------------------------------------------------
// Each sampler reads its own texture unit (found writing the test below: a sampler had no flat
// component, so loading one moved no word and every sampler read unit 0).

TEST(Executor, EachSamplerReadsItsOwnUnit) {
  Kernel k(R"(#version 450
uniform sampler2D first;
uniform sampler2D second;
layout(location = 0) out vec4 color;
void main() { color = vec4(texture(first, vec2(0.5)).x, texture(second, vec2(0.5)).x, 0.0, 0.0); }
)",
           ExecLimits{}, Stage::Fragment);
  const texture::Texture one = rgba32f_texture(1, 1, {1, 0, 0, 1}, texture::Filter::Nearest);
  const texture::Texture two = rgba32f_texture(1, 1, {2, 0, 0, 1}, texture::Filter::Nearest);
  k.inv().bind_texture(3, &one);
  k.inv().bind_texture(5, &two);
  k.begin(4);
  k.set("first", 0, 0, 3);
  k.set("second", 0, 0, 5);
  k.run();
  for (int l = 0; l < 4; ++l) {
    EXPECT_EQ(k.f32("color", l, 0), 1.0f) << "lane " << l;
    EXPECT_EQ(k.f32("color", l, 1), 2.0f) << "lane " << l;
  }
}

// ---------------------------------------------------------------------------------------------
// Texture sampling at coordinates past int's range (fuzz_glsl): defined, and llvmpipe's. A width
// that is not a power of two wraps GL_REPEAT through the coordinate's fraction (texture/filter.cpp),
// which is 0 for ±1e20 and, for nearest filtering, just below 1 for NaN.

TEST(Executor, TextureCoordinatesPastIntRangeAreDefined) {
  Kernel k(R"(#version 450
layout(binding = 0) uniform sampler2D linear_tex;
layout(binding = 1) uniform sampler2D nearest_tex;
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
void main() { color = vec4(texture(linear_tex, uv).x, texture(nearest_tex, uv).x, 0.0, 0.0); }
)",
           ExecLimits{}, Stage::Fragment);
  // Three texels in a row, red 1, 2, 3; repeat wrapping.
  const std::vector<float> texels = {1, 0, 0, 1, 2, 0, 0, 1, 3, 0, 0, 1};
  const texture::Texture linear = rgba32f_texture(3, 1, texels, texture::Filter::Linear);
  const texture::Texture nearest = rgba32f_texture(3, 1, texels, texture::Filter::Nearest);
  k.inv().bind_texture(0, &linear);
  k.inv().bind_texture(1, &nearest);
  const float uv[4][2] = {{0.5f, 0.5f}, {1e20f, 0.5f}, {-1e20f, 0.5f}, {kNaN, 0.5f}};
  k.begin(4);
  k.set("linear_tex", 0, 0, 0);
  k.set("nearest_tex", 0, 0, 1);
  for (int l = 0; l < 4; ++l)
    for (int c = 0; c < 2; ++c) k.set_f32("uv", l, std::uint32_t(c), uv[l][c]);
  k.run();
  EXPECT_TRUE(same(2.0f, k.f32("color", 0, 0)));  // in range: the middle texel, unfiltered
  EXPECT_TRUE(same(2.0f, k.f32("color", 0, 1)));
  for (int l = 1; l < 3; ++l) {
    SCOPED_TRACE("u = " + std::to_string(uv[l][0]));
    // Fraction 0: linear reads texels 2 and 0 half and half (once 1e20 with a weight from INT_MIN),
    // nearest reads texel 0.
    EXPECT_TRUE(same(2.0f, k.f32("color", l, 0)));
    EXPECT_TRUE(same(1.0f, k.f32("color", l, 1)));
  }
  EXPECT_TRUE(std::isnan(k.f32("color", 3, 0)));  // NaN weights
  EXPECT_TRUE(same(3.0f, k.f32("color", 3, 1)));  // the fraction just below 1: the last texel
}

// ---------------------------------------------------------------------------------------------
// A thread's state of an executable (local()) is freed once the executable is gone (fuzz_pipeline:
// kept, every program ever run held its arena on every thread that ran it, and repeated renders
// with GLSL programs grew by megabytes a second). Measured on glibc's heap.

TEST(Executor, ThreadStateOfGoneExecutablesIsFreed) {
  const std::vector<std::uint32_t> spirv = compile_stage(Stage::Vertex, R"(#version 450
layout(location = 0) in vec4 a;
out vec4 r;
void main() { r = a * a + vec4(1.0); }
)");
  auto run_one = [&] {
    const Executable exe(read_module(spirv));
    Invocations& inv = exe.local();
    inv.begin(1);
    inv.run();
  };
  run_one();  // warm: this thread's map and the first executable's state
  const std::size_t before = mallinfo2().uordblks;
  for (int i = 0; i < 300; ++i) run_one();
  const std::size_t after = mallinfo2().uordblks;
  // Each state holds an arena of at least 256 lanes x 4 bytes a row: 300 kept would be megabytes.
  EXPECT_LT(after, before + (std::size_t(1) << 20)) << "heap grew from " << before << " to " << after;
}

}  // namespace
}  // namespace tessref::shader::test
