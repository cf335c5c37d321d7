#include "draw/vertex_format.h"

#include <bit>
#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

namespace tessref::draw {
namespace {

using CT = ComponentType;

float component(const AttributeValue& v, int i) { return std::bit_cast<float>(v.words[std::size_t(i)]); }

template <typename T>
AttributeValue convert(const VertexFormat& f, std::initializer_list<T> values) {
  std::byte bytes[64] = {};
  std::size_t at = 0;
  for (T v : values) {
    std::memcpy(bytes + at, &v, sizeof v);
    at += sizeof v;
  }
  return convert_element(f, bytes);
}

TEST(VertexFormat, GlsRulesOnLegalCombinations) {
  EXPECT_FALSE(format_error({4, false, CT::Float, false, AttribPointer::Float}));
  EXPECT_FALSE(format_error({4, true, CT::UnsignedByte, true, AttribPointer::Float}));
  EXPECT_FALSE(format_error({4, true, CT::Int2101010Rev, true, AttribPointer::Float}));
  EXPECT_FALSE(format_error({3, false, CT::UnsignedInt10F11F11FRev, false, AttribPointer::Float}));
  EXPECT_FALSE(format_error({2, false, CT::Short, false, AttribPointer::Integer}));
  EXPECT_FALSE(format_error({4, false, CT::Double, false, AttribPointer::Double}));
  // GL_INVALID_OPERATION: packed types need size 4 (or BGRA); 10F_11F_11F needs 3.
  EXPECT_TRUE(format_error({3, false, CT::Int2101010Rev, true, AttribPointer::Float}));
  EXPECT_TRUE(format_error({4, false, CT::UnsignedInt10F11F11FRev, false, AttribPointer::Float}));
  // BGRA: ubyte or packed, normalized.
  EXPECT_TRUE(format_error({4, true, CT::UnsignedByte, false, AttribPointer::Float}));
  EXPECT_TRUE(format_error({4, true, CT::Float, false, AttribPointer::Float}));
  EXPECT_TRUE(format_error({4, true, CT::UnsignedByte, true, AttribPointer::Integer}));
  // IPointer takes integers only, LPointer doubles only.
  EXPECT_TRUE(format_error({4, false, CT::Float, false, AttribPointer::Integer}));
  EXPECT_TRUE(format_error({4, false, CT::Float, false, AttribPointer::Double}));
  EXPECT_TRUE(format_error({4, false, CT::Int2101010Rev, false, AttribPointer::Integer}));
  // normalized with a float type: GL ignores it, a scene may not say it.
  const auto e = format_error({3, false, CT::Float, true, AttribPointer::Float});
  ASSERT_TRUE(e);
  EXPECT_NE(e->find("normalized"), std::string::npos);
}

TEST(VertexFormat, ElementSizes) {
  EXPECT_EQ(element_bytes({3, false, CT::Float, false, AttribPointer::Float}), 12u);
  EXPECT_EQ(element_bytes({3, false, CT::UnsignedByte, true, AttribPointer::Float}), 3u);
  EXPECT_EQ(element_bytes({4, false, CT::Int2101010Rev, true, AttribPointer::Float}), 4u);
  EXPECT_EQ(element_bytes({3, false, CT::Double, false, AttribPointer::Double}), 24u);
  EXPECT_EQ(element_bytes({2, false, CT::HalfFloat, false, AttribPointer::Float}), 4u);
}

// GL 4.5, equation 2.2: f = c / (2^b - 1), with the ends exact; rounded as llvmpipe rounds it
// (the integer as a float times the reciprocal as a float), which the GL comparison checks.
TEST(VertexFormat, UnsignedNormalizedEndsAndRounding) {
  for (int bits : {2, 8, 10, 16, 32}) {
    EXPECT_EQ(unsigned_normalized(0, bits), 0.0f) << bits;
    EXPECT_EQ(unsigned_normalized(std::uint32_t((std::uint64_t(1) << bits) - 1), bits), 1.0f) << bits;
  }
  for (std::uint32_t c = 0; c < 65536; ++c) {
    EXPECT_EQ(unsigned_normalized(c, 16), float(c) * float(1.0 / 65535.0)) << c;
    // Within one ulp of the real quotient.
    const double exact = double(c) / 65535.0, f = unsigned_normalized(c, 16);
    EXPECT_LE(std::abs(f - exact), std::abs(double(std::nextafter(float(f), 2.0f)) - f)) << c;
  }
}

// GL 4.2's rule (equation 2.3): f = max(c / (2^(b-1) - 1), -1), so that -2^(b-1) and -(2^(b-1)-1)
// both give -1 and 0 is exactly 0.
TEST(VertexFormat, SignedNormalizedGl42Rule) {
  EXPECT_EQ(signed_normalized(-128, 8), -1.0f);
  EXPECT_EQ(signed_normalized(-127, 8), -1.0f);
  EXPECT_EQ(signed_normalized(0, 8), 0.0f);
  EXPECT_EQ(signed_normalized(127, 8), 1.0f);
  EXPECT_EQ(signed_normalized(64, 8), 64.0f * float(1.0 / 127.0));
  EXPECT_EQ(signed_normalized(-32768, 16), -1.0f);
  EXPECT_EQ(signed_normalized(-2, 2), -1.0f);
  EXPECT_EQ(signed_normalized(1, 2), 1.0f);
  EXPECT_EQ(signed_normalized(-2147483647 - 1, 32), -1.0f);
  EXPECT_EQ(signed_normalized(2147483647, 32), 1.0f);
}

TEST(VertexFormat, MissingComponentsAreZeroZeroZeroOne) {
  const AttributeValue v = convert<float>({2, false, CT::Float, false, AttribPointer::Float}, {5.0f, 6.0f});
  EXPECT_EQ(component(v, 0), 5.0f);
  EXPECT_EQ(component(v, 1), 6.0f);
  EXPECT_EQ(component(v, 2), 0.0f);
  EXPECT_EQ(component(v, 3), 1.0f);
  const AttributeValue i = convert<std::int16_t>({1, false, CT::Short, false, AttribPointer::Integer}, {-7});
  EXPECT_EQ(std::int32_t(i.words[0]), -7);
  EXPECT_EQ(i.words[1], 0u);
  EXPECT_EQ(i.words[3], 1u);  // an integer 1, not 1.0f's bits
  const AttributeValue d = convert<double>({3, false, CT::Double, false, AttribPointer::Double}, {1.5, -2.0, 0.25});
  EXPECT_EQ(d.word_count, 8);
  double w;
  const std::uint64_t b = std::uint64_t(d.words[6]) | (std::uint64_t(d.words[7]) << 32);
  std::memcpy(&w, &b, 8);
  EXPECT_EQ(w, 1.0);
}

TEST(VertexFormat, IntegersThroughVertexAttribPointer) {
  const AttributeValue u = convert<std::uint8_t>({4, false, CT::UnsignedByte, true, AttribPointer::Float}, {0, 51, 255, 128});
  EXPECT_EQ(component(u, 0), 0.0f);
  EXPECT_EQ(component(u, 1), 51.0f * float(1.0 / 255.0));  // one ulp above 0.2f, as llvmpipe gives
  EXPECT_EQ(component(u, 2), 1.0f);
  EXPECT_EQ(component(u, 3), 128.0f * float(1.0 / 255.0));
  const AttributeValue raw = convert<std::int32_t>({2, false, CT::Int, false, AttribPointer::Float}, {-3, 16777217});
  EXPECT_EQ(component(raw, 0), -3.0f);
  EXPECT_EQ(component(raw, 1), 16777216.0f);  // round to nearest even, as the conversion to float
  const AttributeValue fixed = convert<std::int32_t>({1, false, CT::Fixed, false, AttribPointer::Float}, {-98304});
  EXPECT_EQ(component(fixed, 0), -1.5f);
  const AttributeValue half = convert<std::uint16_t>({2, false, CT::HalfFloat, false, AttribPointer::Float}, {0x3c00, 0x0001});
  EXPECT_EQ(component(half, 0), 1.0f);
  EXPECT_EQ(component(half, 1), std::ldexp(1.0f, -24));  // the smallest subnormal half, exact
}

TEST(VertexFormat, BgraSwapsRedAndBlue) {
  const AttributeValue v = convert<std::uint8_t>({4, true, CT::UnsignedByte, true, AttribPointer::Float}, {255, 0, 51, 0});
  EXPECT_EQ(component(v, 0), 51.0f * float(1.0 / 255.0));  // R is the third byte
  EXPECT_EQ(component(v, 1), 0.0f);
  EXPECT_EQ(component(v, 2), 1.0f);  // B the first
  EXPECT_EQ(component(v, 3), 0.0f);
}

TEST(VertexFormat, Packed2101010) {
  // x = -512 (bits 0-9), y = 511, z = 1, w = -2 (bits 30-31: 0b10).
  const std::uint32_t w = 0x200u | (0x1ffu << 10) | (1u << 20) | (2u << 30);
  const AttributeValue n = convert<std::uint32_t>({4, false, CT::Int2101010Rev, true, AttribPointer::Float}, {w});
  EXPECT_EQ(component(n, 0), -1.0f);
  EXPECT_EQ(component(n, 1), 1.0f);
  EXPECT_EQ(component(n, 2), float(1.0 / 511.0));
  EXPECT_EQ(component(n, 3), -1.0f);
  const AttributeValue raw = convert<std::uint32_t>({4, false, CT::Int2101010Rev, false, AttribPointer::Float}, {w});
  EXPECT_EQ(component(raw, 0), -512.0f);
  EXPECT_EQ(component(raw, 3), -2.0f);
  const AttributeValue u = convert<std::uint32_t>({4, false, CT::UnsignedInt2101010Rev, true, AttribPointer::Float}, {w});
  EXPECT_EQ(component(u, 0), 512.0f * float(1.0 / 1023.0));
  EXPECT_EQ(component(u, 3), 2.0f * float(1.0 / 3.0));
  const AttributeValue bgra = convert<std::uint32_t>({4, true, CT::UnsignedInt2101010Rev, true, AttribPointer::Float}, {w});
  EXPECT_EQ(component(bgra, 0), float(1.0 / 1023.0));    // R from bits 20-29
  EXPECT_EQ(component(bgra, 2), 512.0f * float(1.0 / 1023.0));  // B from bits 0-9
}

TEST(VertexFormat, Packed10F11F11F) {
  // x = 1.0 (11-bit: exponent 15, mantissa 0), y = 0.5, z = 64512 (10-bit: the largest finite).
  const std::uint32_t w = (15u << 6) | ((14u << 6) << 11) | (((30u << 5) | 31u) << 22);
  const AttributeValue v = convert<std::uint32_t>({3, false, CT::UnsignedInt10F11F11FRev, false, AttribPointer::Float}, {w});
  EXPECT_EQ(component(v, 0), 1.0f);
  EXPECT_EQ(component(v, 1), 0.5f);
  EXPECT_EQ(component(v, 2), 64512.0f);
  EXPECT_EQ(component(v, 3), 1.0f);
  EXPECT_EQ(unsigned_float11(1), std::ldexp(1.0f, -20));  // subnormal: 1/64 * 2^-14
  EXPECT_TRUE(std::isinf(unsigned_float11(31u << 6)));
  EXPECT_TRUE(std::isnan(unsigned_float10((31u << 5) | 1u)));
}

TEST(VertexFormat, HalfRoundTripsEveryFiniteHalf) {
  for (std::uint32_t h = 0; h < 0x10000; ++h) {
    if ((h & 0x7c00) == 0x7c00) continue;  // inf and NaN
    EXPECT_EQ(float_to_half(half_to_float(std::uint16_t(h))), h) << h;
  }
}

TEST(VertexFormat, Names) {
  EXPECT_EQ(component_type("GL_UNSIGNED_INT_2_10_10_10_REV"), CT::UnsignedInt2101010Rev);
  EXPECT_FALSE(component_type("GL_FLOAT_VEC3"));
  EXPECT_STREQ(gl_name(CT::HalfFloat), "GL_HALF_FLOAT");
}

}  // namespace
}  // namespace tessref::draw
