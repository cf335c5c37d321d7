// Attachment formats (raster/color_format.h, common/fixed_point.h): the conversions as GL states
// them where it fixes them, as llvmpipe rounds where it leaves a choice, and the draw writing
// each format (output locations to draw buffers, blending per format, a 24-bit depth test).
#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

#include "common/fixed_point.h"
#include "raster/clear.h"
#include "raster/color_format.h"
#include "raster/framebuffer.h"

namespace tessref {
namespace {

TEST(ColorFormat, Unorm8RoundsToNearestEvenAndClamps) {
  EXPECT_EQ(fixed::unorm8_from_float(0.0f), 0);
  EXPECT_EQ(fixed::unorm8_from_float(1.0f), 255);
  EXPECT_EQ(fixed::unorm8_from_float(-3.0f), 0);
  EXPECT_EQ(fixed::unorm8_from_float(7.0f), 255);
  EXPECT_EQ(fixed::unorm8_from_float(std::nanf("")), 0);
  EXPECT_EQ(fixed::unorm8_from_float(0.5f), 128);           // 127.5: ties to even
  EXPECT_EQ(fixed::unorm8_from_float(1.5f / 255.0f), 2);    // 1.5 in float: ties to even
  EXPECT_EQ(fixed::unorm8_from_float(2.5f / 255.0f), 2);
  for (int k = 0; k <= 255; ++k) EXPECT_EQ(fixed::unorm8_from_float(fixed::unorm8_to_float(std::uint8_t(k))), k);
}

// Not GL's exact a * b / 255 rounded: llvmpipe's shift form is off by one step where the exact
// product sits within 1/255 of a half (counted: those are all it gets wrong).
TEST(ColorFormat, Unorm8ProductIsLlvmpipesApproximation) {
  int not_nearest = 0;
  for (int a = 0; a <= 255; ++a)
    for (int b = 0; b <= 255; ++b) {
      const double exact = a * b / 255.0;
      const double error = std::abs(fixed::unorm8_mul(a, b) - exact);
      ASSERT_LT(error, 0.5 + 1.0 / 255.0) << a << " * " << b;
      not_nearest += error > 0.5;
    }
  EXPECT_GT(not_nearest, 0);
  EXPECT_LT(not_nearest, 256 * 256 / 100);
  EXPECT_EQ(fixed::unorm8_mul(255, 255), 255);
  EXPECT_EQ(fixed::unorm8_mul(169, 212), 140);  // 140.5: llvmpipe's form rounds this half down
}

TEST(ColorFormat, Depth24IsOneToOneAndOrdered) {
  EXPECT_EQ(fixed::depth24_from_float(1.0f), 16777215u);
  EXPECT_EQ(fixed::depth24_from_float(0.0f), 0u);
  EXPECT_EQ(fixed::depth24_from_float(2.0f), 16777215u);
  float previous = -1.0f;
  for (std::uint32_t k = 0; k <= 16777215u; k += (k < 4096 || k > 16777215u - 4096) ? 1 : 4093) {
    const float z = fixed::depth24_to_float(k);
    ASSERT_EQ(fixed::depth24_from_float(z), k);
    ASSERT_LT(previous, z);
    previous = z;
  }
}

TEST(ColorFormat, HalfRoundsTowardZero) {
  EXPECT_EQ(fixed::half_round_toward_zero(1.0f), 1.0f);
  EXPECT_EQ(fixed::half_round_toward_zero(1.0f + 1.0f / 2048.0f), 1.0f);      // below the next half, 1 + 2^-10
  EXPECT_EQ(fixed::half_round_toward_zero(1.0f + 1.0f / 1024.0f), 1.0f + 1.0f / 1024.0f);
  EXPECT_EQ(fixed::half_round_toward_zero(-333.33f), -333.25f);
  EXPECT_EQ(fixed::half_round_toward_zero(1e6f), 65504.0f);
  EXPECT_EQ(fixed::half_round_toward_zero(-1e6f), -65504.0f);
  EXPECT_TRUE(std::isinf(fixed::half_round_toward_zero(INFINITY)));
  EXPECT_TRUE(std::isnan(fixed::half_round_toward_zero(std::nanf(""))));
  const float step = std::ldexp(1.0f, -24);  // the smallest subnormal half
  EXPECT_EQ(fixed::half_round_toward_zero(2.9f * step), 2.0f * step);
  EXPECT_EQ(fixed::half_round_toward_zero(0.9f * step), 0.0f);
}

// The tables against GL's equations evaluated in double (test time only: the renderer takes no
// pow() whose bits would depend on the C library).
TEST(ColorFormat, SrgbMatchesGlsEquations) {
  for (int k = 0; k <= 255; ++k) {
    const double cs = k / 255.0;
    const double cl = cs <= 0.04045 ? cs / 12.92 : std::pow((cs + 0.055) / 1.055, 2.4);
    EXPECT_EQ(srgb_decode(std::uint8_t(k)), float(cl)) << k;
  }
  const auto encode = [](double cl) {
    const double cs = cl <= 0.0 ? 0.0 : cl < 0.0031308 ? 12.92 * cl : cl < 1.0 ? 1.055 * std::pow(cl, 0.41666) - 0.055 : 1.0;
    return int(std::floor(cs * 255.0 + 0.5));
  };
  for (int i = 0; i <= 100000; ++i) {
    const float l = float(i) / 100000.0f;
    ASSERT_EQ(srgb_encode(l), encode(l)) << l;
  }
  // Every 8-bit value survives decoding and encoding (GL's requirement for sRGB round trips).
  for (int k = 0; k <= 255; ++k) EXPECT_EQ(srgb_encode(srgb_decode(std::uint8_t(k))), k);
  EXPECT_EQ(srgb_encode(-1.0f), 0);
  EXPECT_EQ(srgb_encode(std::nanf("")), 0);
  EXPECT_EQ(srgb_encode(5.0f), 255);
}

TEST(ColorFormat, BlendingUsesEachFormatsArithmetic) {
  BlendState b;
  b.enabled = true;
  b.src_rgb = b.src_alpha = BlendFactor::kSrcAlpha;
  b.dst_rgb = b.dst_alpha = BlendFactor::kOneMinusSrcAlpha;
  const glm::vec4 s(2.0f, 0.5f, -1.0f, 0.4f), d(0.2f, 0.2f, 0.2f, 1.0f);
  // Float: nothing clamped.
  EXPECT_FLOAT_EQ(blended_color(ColorFormat::kRgba32F, false, b, s, d).r, 2.0f * 0.4f + 0.2f * 0.6f);
  // 8 bits: source clamped to 1 (255), alpha 0.4 -> 102, destination 0.2 -> 51.
  const glm::vec4 r8 = blended_color(ColorFormat::kRgba8, false, b, s, d);
  EXPECT_EQ(r8.r, fixed::unorm8_to_float(std::uint8_t(fixed::unorm8_mul(255, 102) + fixed::unorm8_mul(51, 153))));
  EXPECT_EQ(r8.b, fixed::unorm8_to_float(std::uint8_t(fixed::unorm8_mul(51, 153))));
  // sRGB with GL_FRAMEBUFFER_SRGB: the destination decoded, the result encoded; without it, RGBA8.
  const glm::vec4 stored = stored_color(ColorFormat::kSrgb8Alpha8, true, glm::vec4(0.2f));
  const glm::vec4 rs = blended_color(ColorFormat::kSrgb8Alpha8, true, b, glm::vec4(0.5f, 0.5f, 0.5f, 0.4f), stored);
  const float linear = 0.5f * 0.4f + srgb_decode(fixed::unorm8_from_float(stored.r)) * (1.0f - 0.4f);
  EXPECT_EQ(rs.r, fixed::unorm8_to_float(srgb_encode(linear)));
  EXPECT_EQ(blended_color(ColorFormat::kSrgb8Alpha8, false, b, s, d), r8);
  // Half: blended in float, then rounded toward zero.
  EXPECT_EQ(blended_color(ColorFormat::kRgba16F, false, b, glm::vec4(1000.1f, 0, 0, 1), d).r, 1000.0f);
}

TEST(ColorFormat, ClearConvertsToEachDrawBuffersFormat) {
  Framebuffer fb(4, 2);
  fb.set_draw_buffers(3);
  fb.color_format = {ColorFormat::kRgba8, ColorFormat::kSrgb8Alpha8, ColorFormat::kRgba16F};
  fb.depth_format = DepthFormat::k24;
  RasterState state = gl_initial_state();
  state.framebuffer_srgb = true;
  clear_buffers(fb, state, glm::vec4(0.3f, 0.5f, 1000.1f, 1.0f), 0.3f);  // 0.3 * 255 is 76.5 in float: 76
  EXPECT_EQ(fb.color[0], glm::vec4(fixed::unorm8_to_float(76), fixed::unorm8_to_float(128), 1.0f, 1.0f));
  EXPECT_EQ(fb.aux[0].r, fixed::unorm8_to_float(srgb_encode(0.3f)));
  EXPECT_EQ(fb.more[0][0].b, 1000.0f);
  EXPECT_EQ(fb.depth[7], fixed::quantize_depth24(0.3f));
  EXPECT_NE(fb.depth[7], 0.3f);
}

}  // namespace
}  // namespace tessref
