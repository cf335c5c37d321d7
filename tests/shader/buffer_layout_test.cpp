// Uniform blocks read from buffer bytes through the module's explicit layout: std140's offsets,
// array strides (16 bytes even for a float), matrix strides, row-major matrices, nested structs
// and doubles, checked word by word against the rules of GL 4.5 section 7.6.2.2.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "shader/buffer_layout.h"
#include "shader_test_util.h"

namespace tessref::shader {
namespace {

using test::as_double;
using test::as_float;

// A buffer of floats f(k) = k + 0.5 at byte 4k, so that each word read names the byte it came from.
std::vector<std::byte> numbered_bytes(std::size_t n) {
  std::vector<std::byte> b(n);
  for (std::size_t k = 0; k * 4 + 4 <= n; ++k) {
    const float f = float(k) + 0.5f;
    std::memcpy(b.data() + 4 * k, &f, 4);
  }
  return b;
}

std::uint32_t block_type(const Module& m, const std::string& name) {
  for (const auto& [id, n] : m.names)
    if (n == name) return id;
  throw std::runtime_error("no type " + name);
}

TEST(BufferLayout, Std140OffsetsStridesAndMatrices) {
  const Module m = read_module(test::compile_stage(Stage::Fragment, R"(#version 450 core
struct Inner { float a; vec2 b; };
layout(std140, binding = 0) uniform B {
  vec3 v;                   // offset 0
  float f;                  // 12: packs after the vec3
  mat3 m;                   // 16: columns 16 bytes apart
  float arr[3];             // 64: stride 16
  layout(row_major) mat2x3 r;  // 112: rows (vec2) 16 bytes apart
  Inner inner;              // 160: a struct aligned to 16; b at 168
};
layout(location = 0) out vec4 o;
void main() { o = vec4(v, f) + vec4(m[1], arr[2]) + vec4(r[1].xy, inner.a, inner.b.y); }
)"));
  const std::uint32_t type = block_type(m, "B");
  EXPECT_EQ(explicit_layout_extent(m, type), 176u);
  const std::vector<std::byte> bytes = numbered_bytes(176);
  std::vector<std::uint32_t> w(m.type(type).words);
  read_explicit_layout(m, type, bytes, w.data());
  // Flattened: v(3) f(1) m(9) arr(3) r(6: 2 columns of 3) inner(3).
  ASSERT_EQ(w.size(), 25u);
  auto at = [&](std::size_t word) { return as_float(w[word]); };
  // The float at byte 4k is k + 0.5.
  EXPECT_EQ(at(0), 0.5f);   // v.x: byte 0
  EXPECT_EQ(at(3), 3.5f);   // f: byte 12
  EXPECT_EQ(at(4), 4.5f);   // m[0].x: byte 16
  EXPECT_EQ(at(7), 8.5f);   // m[1].x: byte 32
  EXPECT_EQ(at(12), 14.5f); // m[2].z: byte 56
  EXPECT_EQ(at(13), 16.5f); // arr[0]: byte 64
  EXPECT_EQ(at(15), 24.5f); // arr[2]: byte 96
  // Row-major mat2x3: element (column c, row r) at 112 + 16 r + 4 c.
  EXPECT_EQ(at(16), 28.5f); // r[0][0]: byte 112
  EXPECT_EQ(at(17), 32.5f); // r[0][1]: byte 128
  EXPECT_EQ(at(19), 29.5f); // r[1][0]: byte 116
  EXPECT_EQ(at(21), 37.5f); // r[1][2]: byte 148
  EXPECT_EQ(at(22), 40.5f); // inner.a: byte 160
  EXPECT_EQ(at(23), 42.5f); // inner.b.x: byte 168
  EXPECT_EQ(at(24), 43.5f); // inner.b.y: byte 172
}

TEST(BufferLayout, DoublesBoolsAndShortRanges) {
  const Module m = read_module(test::compile_stage(Stage::Fragment, R"(#version 450 core
layout(std140, binding = 2) uniform D {
  bool flag;    // 0: a 32-bit word
  dvec3 d;      // 32: dvec3 aligns to 32 bytes
  ivec2 i;      // 56
};
layout(location = 0) out vec4 o;
void main() { o = vec4(flag ? float(d.y) : 0.0, float(i.y), 0.0, 1.0); }
)"));
  const std::uint32_t type = block_type(m, "D");
  EXPECT_EQ(explicit_layout_extent(m, type), 64u);
  std::vector<std::byte> bytes(64, std::byte{0});
  const std::uint32_t seven = 7;  // a bool is any non-zero word
  std::memcpy(bytes.data(), &seven, 4);
  const double d[3] = {1.25, -2.5, 1e300};
  std::memcpy(bytes.data() + 32, d, sizeof d);
  const std::int32_t iv[2] = {-3, 12};
  std::memcpy(bytes.data() + 56, iv, sizeof iv);
  std::vector<std::uint32_t> w(m.type(type).words);
  read_explicit_layout(m, type, bytes, w.data());
  ASSERT_EQ(w.size(), 1u + 6u + 2u);
  EXPECT_EQ(w[0], 7u);  // glslang keeps a block's bool as a uint (the shader compares it with 0)
  EXPECT_EQ(as_double(w[1], w[2]), 1.25);
  EXPECT_EQ(as_double(w[3], w[4]), -2.5);
  EXPECT_EQ(as_double(w[5], w[6]), 1e300);
  EXPECT_EQ(std::int32_t(w[7]), -3);
  EXPECT_EQ(std::int32_t(w[8]), 12);
  EXPECT_THROW(read_explicit_layout(m, type, std::span(bytes).first(60), w.data()), SpirvError);
}

}  // namespace
}  // namespace tessref::shader
