// tessref's vertex attribute conversions (draw/vertex_format.h) against the GL driver's, bit for
// bit: every value of each 8- and 16-bit type, and sampled 32-bit and packed words, fetched by the
// driver through glVertexAttrib*Pointer and read back by transform feedback from a vertex shader
// that passes the attribute through.
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include "draw/vertex_format.h"
#include "gl_fixture.h"
#include "glref/feedback_draw.h"
#include "glref/gl_error.h"
#include "glref/gl_program.h"

namespace tessref::glref {
namespace {

using draw::AttribPointer;
using draw::ComponentType;
using draw::VertexFormat;

// The attribute as the driver's vertex shader sees it, 4 words (8 for doubles) per element.
std::vector<std::uint32_t> driver_values(const VertexFormat& f, const std::vector<std::byte>& data, std::size_t elements) {
  const bool dbl = f.pointer == AttribPointer::Double, integer = f.pointer == AttribPointer::Integer;
  const std::string type = dbl ? "dvec4" : integer ? "ivec4" : "vec4";
  const std::string vs = "#version 450 core\nlayout(location = 0) in " + type + " a;\n" +
                         (integer || dbl ? "flat " : "") + "out " + type + " v;\nvoid main() { v = a; gl_Position = vec4(0.0); }\n";
  const Program program = link_program({{GL_VERTEX_SHADER, vs, "passthrough.vert"}}, FeedbackVaryings{{"v"}, true});
  GLuint vao = 0, buffers[2] = {0, 0}, queries[2] = {0, 0};
  glGenVertexArrays(1, &vao);
  glGenBuffers(2, buffers);
  glGenQueries(2, queries);
  glBindVertexArray(vao);
  glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size()), data.data(), GL_STATIC_DRAW);
  const GLenum gl_type = [&] {
    switch (f.type) {
      case ComponentType::Byte: return GLenum(GL_BYTE);
      case ComponentType::UnsignedByte: return GLenum(GL_UNSIGNED_BYTE);
      case ComponentType::Short: return GLenum(GL_SHORT);
      case ComponentType::UnsignedShort: return GLenum(GL_UNSIGNED_SHORT);
      case ComponentType::Int: return GLenum(GL_INT);
      case ComponentType::UnsignedInt: return GLenum(GL_UNSIGNED_INT);
      case ComponentType::Fixed: return GLenum(GL_FIXED);
      case ComponentType::HalfFloat: return GLenum(GL_HALF_FLOAT);
      case ComponentType::Float: return GLenum(GL_FLOAT);
      case ComponentType::Double: return GLenum(GL_DOUBLE);
      case ComponentType::Int2101010Rev: return GLenum(GL_INT_2_10_10_10_REV);
      case ComponentType::UnsignedInt2101010Rev: return GLenum(GL_UNSIGNED_INT_2_10_10_10_REV);
      case ComponentType::UnsignedInt10F11F11FRev: return GLenum(GL_UNSIGNED_INT_10F_11F_11F_REV);
    }
    return GLenum(GL_NONE);
  }();
  const GLint size = f.bgra ? GL_BGRA : f.size;
  if (integer) glVertexAttribIPointer(0, size, gl_type, 0, nullptr);
  else if (dbl) glVertexAttribLPointer(0, size, GL_DOUBLE, 0, nullptr);
  else glVertexAttribPointer(0, size, gl_type, f.normalized ? GL_TRUE : GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(0);
  const std::size_t words = dbl ? 8 : 4;
  glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, buffers[1]);
  glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, GLsizeiptr(elements * words * 4), nullptr, GL_STATIC_READ);
  glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, buffers[1]);
  program.use();
  glEnable(GL_RASTERIZER_DISCARD);
  draw_with_feedback(GL_POINTS, queries[0], queries[1], [&] { glDrawArrays(GL_POINTS, 0, GLsizei(elements)); },
                     "vertex format capture", "feedback buffer too small");
  glDisable(GL_RASTERIZER_DISCARD);
  std::vector<std::uint32_t> out(elements * words);
  glGetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER, 0, GLsizeiptr(out.size() * 4), out.data());
  glBindVertexArray(0);
  glDeleteVertexArrays(1, &vao);
  glDeleteBuffers(2, buffers);
  glDeleteQueries(2, queries);
  check_gl("vertex format capture");
  return out;
}

// Mesa 22.3's GL_FIXED: c / 65535, where GL says a 16.16 fixed-point value (c / 65536).
float mesa_fixed(std::int32_t c) { return float(c) * float(1.0 / 65535.0); }

// Elements differing from tessref's conversion, with the first few listed. mesa_fixed_rule:
// compare GL_FIXED against Mesa's rule instead (to show that is the one difference).
std::size_t count_differences(const VertexFormat& f, const std::vector<std::byte>& data, std::string& first,
                              bool mesa_fixed_rule = false) {
  const std::size_t stride = draw::element_bytes(f);
  const std::size_t elements = data.size() / stride;
  const std::vector<std::uint32_t> gl = driver_values(f, data, elements);
  const std::size_t words = f.pointer == AttribPointer::Double ? 8 : 4;
  std::size_t differ = 0;
  for (std::size_t e = 0; e < elements; ++e) {
    draw::AttributeValue ours = draw::convert_element(f, data.data() + e * stride);
    if (mesa_fixed_rule)
      for (int c = 0; c < f.size; ++c) {
        std::int32_t x;
        std::memcpy(&x, data.data() + e * stride + 4 * std::size_t(c), 4);
        ours.words[std::size_t(c)] = std::bit_cast<std::uint32_t>(mesa_fixed(x));
      }
    for (std::size_t w = 0; w < words; ++w) {
      const std::uint32_t a = ours.words[w], b = gl[e * words + w];
      // NaN payloads are not GL's to fix: any NaN matches any NaN.
      const bool both_nan = words == 4 && f.pointer == AttribPointer::Float && std::isnan(std::bit_cast<float>(a)) &&
                            std::isnan(std::bit_cast<float>(b));
      if (a != b && !both_nan) {
        if (differ < 4)
        {
          char text[160];
          std::snprintf(text, sizeof text, " element %zu word %zu: tessref %.9g (0x%08x), driver %.9g (0x%08x);", e, w,
                        double(std::bit_cast<float>(a)), a, double(std::bit_cast<float>(b)), b);
          first += text;
        }
        ++differ;
        break;
      }
    }
  }
  return differ;
}

// Every value of a 1- or 2-byte component type, one component per element... sized to `size`.
std::vector<std::byte> every_value(std::size_t bytes, int size) {
  const std::size_t values = std::size_t(1) << (8 * bytes);
  std::vector<std::byte> out;
  for (std::size_t v = 0; v < values; v += std::size_t(size))
    for (int c = 0; c < size; ++c) {
      const std::uint32_t x = std::uint32_t((v + std::size_t(c)) % values);
      for (std::size_t b = 0; b < bytes; ++b) out.push_back(std::byte((x >> (8 * b)) & 0xff));
    }
  return out;
}

std::vector<std::byte> random_words(std::size_t n, std::uint32_t seed, bool doubles = false) {
  std::mt19937 rng(seed);
  std::vector<std::byte> out(n * 4);
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t w = rng();
    if (doubles && i % 2) w = (w & 0x800fffffu) | (std::uint32_t(900 + rng() % 250) << 20);  // finite exponents
    std::memcpy(out.data() + 4 * i, &w, 4);
  }
  return out;
}

struct Case {
  const char* name;
  VertexFormat format;
  std::vector<std::byte> data;
};

TEST(VertexFormatsVsLlvmpipe, EveryConversionBitForBit) {
  TESSREF_REQUIRE_GL(ctx);
  ctx->make_current();
  using CT = ComponentType;
  const AttribPointer F = AttribPointer::Float, I = AttribPointer::Integer, L = AttribPointer::Double;
  std::vector<Case> cases{
      {"ubyte normalized", {4, false, CT::UnsignedByte, true, F}, every_value(1, 4)},
      {"byte normalized", {4, false, CT::Byte, true, F}, every_value(1, 4)},
      {"ubyte", {4, false, CT::UnsignedByte, false, F}, every_value(1, 4)},
      {"byte", {3, false, CT::Byte, false, F}, every_value(1, 3)},
      {"ubyte bgra", {4, true, CT::UnsignedByte, true, F}, every_value(1, 4)},
      {"ushort normalized", {4, false, CT::UnsignedShort, true, F}, every_value(2, 4)},
      {"short normalized", {2, false, CT::Short, true, F}, every_value(2, 2)},
      {"ushort", {4, false, CT::UnsignedShort, false, F}, every_value(2, 4)},
      {"short", {1, false, CT::Short, false, F}, every_value(2, 1)},
      {"half", {4, false, CT::HalfFloat, false, F}, every_value(2, 4)},
      {"uint normalized", {4, false, CT::UnsignedInt, true, F}, random_words(4096, 1)},
      {"int normalized", {4, false, CT::Int, true, F}, random_words(4096, 2)},
      {"uint", {4, false, CT::UnsignedInt, false, F}, random_words(4096, 3)},
      {"int", {4, false, CT::Int, false, F}, random_words(4096, 4)},
      {"fixed", {4, false, CT::Fixed, false, F}, random_words(4096, 5)},
      {"double as float", {2, false, CT::Double, false, F}, random_words(4096, 6, true)},
      {"int 2_10_10_10 normalized", {4, false, CT::Int2101010Rev, true, F}, random_words(4096, 7)},
      {"int 2_10_10_10", {4, false, CT::Int2101010Rev, false, F}, random_words(4096, 8)},
      {"uint 2_10_10_10 normalized", {4, false, CT::UnsignedInt2101010Rev, true, F}, random_words(4096, 9)},
      {"uint 2_10_10_10 bgra", {4, true, CT::UnsignedInt2101010Rev, true, F}, random_words(4096, 10)},
      {"int 2_10_10_10 bgra", {4, true, CT::Int2101010Rev, true, F}, random_words(4096, 11)},
      {"10f_11f_11f", {3, false, CT::UnsignedInt10F11F11FRev, false, F}, random_words(4096, 12)},
      {"ibyte", {4, false, CT::Byte, false, I}, every_value(1, 4)},
      {"iushort", {3, false, CT::UnsignedShort, false, I}, every_value(2, 3)},
      {"iint", {2, false, CT::Int, false, I}, random_words(4096, 13)},
      {"ldouble", {4, false, CT::Double, false, L}, random_words(4096, 14, true)},
  };
  // Every 10-bit field value once in each position, and all four 2-bit alphas.
  for (Case& c : cases)
    if (c.format.type == CT::Int2101010Rev || c.format.type == CT::UnsignedInt2101010Rev)
      for (std::uint32_t v = 0; v < 1024; ++v) {
        const std::uint32_t w = v | (v << 10) | (v << 20) | ((v & 3u) << 30);
        const auto* p = reinterpret_cast<const std::byte*>(&w);
        c.data.insert(c.data.end(), p, p + 4);
      }
  for (const Case& c : cases) {
    std::string first;
    const std::size_t differ = count_differences(c.format, c.data, first);
    const std::size_t elements = c.data.size() / draw::element_bytes(c.format);
    std::printf("[ figures  ] %s: %zu of %zu elements differ%s\n", c.name, differ, elements, first.c_str());
    if (c.format.type != CT::Fixed) {
      EXPECT_EQ(differ, 0u) << c.name << ":" << first;
      continue;
    }
    // GL_FIXED: tessref keeps GL's 16.16 rule; the driver's values are Mesa's c / 65535 exactly.
    std::string mesa;
    const std::size_t differ_from_mesa = count_differences(c.format, c.data, mesa, true);
    std::printf("[ figures  ] fixed against Mesa's c / 65535: %zu of %zu elements differ\n", differ_from_mesa, elements);
    EXPECT_EQ(differ_from_mesa, 0u) << mesa;
    EXPECT_EQ(draw::convert_element(c.format, reinterpret_cast<const std::byte*>("\0\0\1\0\0\0\1\0\0\0\0\0\0\0\0\0")).words[0],
              std::bit_cast<std::uint32_t>(1.0f));  // 0x00010000 is 1.0
  }
}

}  // namespace
}  // namespace tessref::glref
