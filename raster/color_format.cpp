#include "raster/color_format.h"

#include <algorithm>

#include "common/fixed_point.h"

namespace tessref {
namespace {

std::uint8_t unorm8(float c) { return fixed::unorm8_from_float(c); }

glm::vec4 clamp01(const glm::vec4& c) {
  glm::vec4 out;
  for (int i = 0; i < 4; ++i) out[i] = c[i] > 0.0f ? (c[i] < 1.0f ? c[i] : 1.0f) : 0.0f;  // NaN: 0
  return out;
}

// Table 17.2's factor for channel c, in 8-bit arithmetic: 1 is 255, 1 - x is 255 - x.
int factor8(BlendFactor f, int c, const int s[4], const int d[4], const int k[4]) {
  switch (f) {
    case BlendFactor::kZero: return 0;
    case BlendFactor::kOne: return 255;
    case BlendFactor::kSrcColor: return s[c];
    case BlendFactor::kOneMinusSrcColor: return 255 - s[c];
    case BlendFactor::kDstColor: return d[c];
    case BlendFactor::kOneMinusDstColor: return 255 - d[c];
    case BlendFactor::kSrcAlpha: return s[3];
    case BlendFactor::kOneMinusSrcAlpha: return 255 - s[3];
    case BlendFactor::kDstAlpha: return d[3];
    case BlendFactor::kOneMinusDstAlpha: return 255 - d[3];
    case BlendFactor::kConstantColor: return k[c];
    case BlendFactor::kOneMinusConstantColor: return 255 - k[c];
    case BlendFactor::kConstantAlpha: return k[3];
    case BlendFactor::kOneMinusConstantAlpha: return 255 - k[3];
    case BlendFactor::kSrcAlphaSaturate: return c == 3 ? 255 : std::min(s[3], 255 - d[3]);
  }
  return 0;
}

glm::vec4 blend_unorm8(const BlendState& b, const glm::vec4& src, const glm::vec4& dst) {
  int s[4], d[4], k[4];
  for (int c = 0; c < 4; ++c) {
    s[c] = unorm8(src[c]);
    d[c] = unorm8(dst[c]);
    k[c] = unorm8(b.constant[c]);
  }
  glm::vec4 out;
  for (int c = 0; c < 4; ++c) {
    const bool alpha = c == 3;
    const BlendEquation eq = alpha ? b.equation_alpha : b.equation_rgb;
    const int fs = factor8(alpha ? b.src_alpha : b.src_rgb, c, s, d, k);
    const int fd = factor8(alpha ? b.dst_alpha : b.dst_rgb, c, s, d, k);
    int r = 0;
    switch (eq) {
      case BlendEquation::kAdd: r = fixed::unorm8_mul(s[c], fs) + fixed::unorm8_mul(d[c], fd); break;
      case BlendEquation::kSubtract: r = fixed::unorm8_mul(s[c], fs) - fixed::unorm8_mul(d[c], fd); break;
      case BlendEquation::kReverseSubtract: r = fixed::unorm8_mul(d[c], fd) - fixed::unorm8_mul(s[c], fs); break;
      case BlendEquation::kMin: r = std::min(s[c], d[c]); break;
      case BlendEquation::kMax: r = std::max(s[c], d[c]); break;
    }
    out[c] = fixed::unorm8_to_float(std::uint8_t(std::clamp(r, 0, 255)));
  }
  return out;
}

glm::vec4 srgb_decoded(const glm::vec4& stored) {
  return glm::vec4(srgb_decode(unorm8(stored.r)), srgb_decode(unorm8(stored.g)), srgb_decode(unorm8(stored.b)),
                   stored.a);
}

}  // namespace

const char* gl_name(ColorFormat f) {
  switch (f) {
    case ColorFormat::kRgba32F: return "GL_RGBA32F";
    case ColorFormat::kRgba16F: return "GL_RGBA16F";
    case ColorFormat::kRgba8: return "GL_RGBA8";
    case ColorFormat::kSrgb8Alpha8: return "GL_SRGB8_ALPHA8";
  }
  return "?";
}

const char* gl_name(DepthFormat f) {
  return f == DepthFormat::k24 ? "GL_DEPTH_COMPONENT24" : "GL_DEPTH_COMPONENT32F";
}

glm::vec4 stored_color(ColorFormat f, bool srgb_write, const glm::vec4& c) {
  switch (f) {
    case ColorFormat::kRgba32F: return c;
    case ColorFormat::kRgba16F:
      return glm::vec4(fixed::half_round_toward_zero(c.r), fixed::half_round_toward_zero(c.g),
                       fixed::half_round_toward_zero(c.b), fixed::half_round_toward_zero(c.a));
    case ColorFormat::kSrgb8Alpha8:
      if (srgb_write) {  // 17.3.9: R, G and B encoded; alpha converted as a linear channel
        const auto e = [](float v) { return fixed::unorm8_to_float(srgb_encode(v)); };
        return glm::vec4(e(c.r), e(c.g), e(c.b), fixed::unorm8_to_float(unorm8(c.a)));
      }
      [[fallthrough]];
    case ColorFormat::kRgba8:
      return glm::vec4(fixed::unorm8_to_float(unorm8(c.r)), fixed::unorm8_to_float(unorm8(c.g)),
                       fixed::unorm8_to_float(unorm8(c.b)), fixed::unorm8_to_float(unorm8(c.a)));
  }
  return c;
}

glm::vec4 blended_color(ColorFormat f, bool srgb_write, const BlendState& b, const glm::vec4& s,
                        const glm::vec4& d) {
  switch (f) {
    case ColorFormat::kRgba32F: return blend(b, s, d);
    case ColorFormat::kRgba16F: return stored_color(f, false, blend(b, s, d));
    case ColorFormat::kSrgb8Alpha8:
      if (srgb_write) {  // 17.3.6.1: the destination's RGB is decoded to linear before blending
        BlendState clamped = b;
        clamped.constant = clamp01(b.constant);
        return stored_color(f, true, blend(clamped, clamp01(s), srgb_decoded(d)));
      }
      [[fallthrough]];
    case ColorFormat::kRgba8: return blend_unorm8(b, s, d);
  }
  return s;
}

}  // namespace tessref
