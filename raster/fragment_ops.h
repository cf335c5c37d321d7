#pragma once
// The per-fragment operations after the fragment shader (GL 4.6 chapter 17): the scissor test,
// the depth test with its function and write mask, blending and the colour write mask, as plain
// state and the functions that apply it to one fragment.
#include <algorithm>

#include <glm/glm.hpp>

namespace tessref {

// glDepthFunc.
enum class DepthFunc { kNever, kLess, kEqual, kLessEqual, kGreater, kNotEqual, kGreaterEqual, kAlways };

// GL 4.6 section 17.3.4: the fragment passes when `z FUNC stored` holds.
inline bool depth_passes(DepthFunc f, float z, float stored) {
  switch (f) {
    case DepthFunc::kNever: return false;
    case DepthFunc::kLess: return z < stored;
    case DepthFunc::kEqual: return z == stored;
    case DepthFunc::kLessEqual: return z <= stored;
    case DepthFunc::kGreater: return z > stored;
    case DepthFunc::kNotEqual: return z != stored;
    case DepthFunc::kGreaterEqual: return z >= stored;
    case DepthFunc::kAlways: return true;
  }
  return false;
}

// glBlendEquationSeparate and glBlendFuncSeparate (GL 4.6 section 17.3.6; dual-source factors
// excluded).
enum class BlendEquation { kAdd, kSubtract, kReverseSubtract, kMin, kMax };
enum class BlendFactor {
  kZero, kOne, kSrcColor, kOneMinusSrcColor, kDstColor, kOneMinusDstColor, kSrcAlpha,
  kOneMinusSrcAlpha, kDstAlpha, kOneMinusDstAlpha, kConstantColor, kOneMinusConstantColor,
  kConstantAlpha, kOneMinusConstantAlpha, kSrcAlphaSaturate
};

struct BlendState {
  bool enabled = false;  // glEnable(GL_BLEND)
  BlendEquation equation_rgb = BlendEquation::kAdd, equation_alpha = BlendEquation::kAdd;
  BlendFactor src_rgb = BlendFactor::kOne, dst_rgb = BlendFactor::kZero;
  BlendFactor src_alpha = BlendFactor::kOne, dst_alpha = BlendFactor::kZero;
  glm::vec4 constant{0.0f};  // glBlendColor
};

// Table 17.2: the factor's value for channel c (3: alpha) of source s and destination d.
inline float blend_factor(BlendFactor f, int c, const glm::vec4& s, const glm::vec4& d, const glm::vec4& k) {
  switch (f) {
    case BlendFactor::kZero: return 0.0f;
    case BlendFactor::kOne: return 1.0f;
    case BlendFactor::kSrcColor: return s[c];
    case BlendFactor::kOneMinusSrcColor: return 1.0f - s[c];
    case BlendFactor::kDstColor: return d[c];
    case BlendFactor::kOneMinusDstColor: return 1.0f - d[c];
    case BlendFactor::kSrcAlpha: return s.a;
    case BlendFactor::kOneMinusSrcAlpha: return 1.0f - s.a;
    case BlendFactor::kDstAlpha: return d.a;
    case BlendFactor::kOneMinusDstAlpha: return 1.0f - d.a;
    case BlendFactor::kConstantColor: return k[c];
    case BlendFactor::kOneMinusConstantColor: return 1.0f - k[c];
    case BlendFactor::kConstantAlpha: return k.a;
    case BlendFactor::kOneMinusConstantAlpha: return 1.0f - k.a;
    case BlendFactor::kSrcAlphaSaturate: return c == 3 ? 1.0f : std::min(s.a, 1.0f - d.a);
  }
  return 0.0f;
}

// Equations of table 17.1. The framebuffer is floating-point, so nothing is clamped (17.3.6.1).
inline glm::vec4 blend(const BlendState& b, const glm::vec4& s, const glm::vec4& d) {
  glm::vec4 out;
  for (int c = 0; c < 4; ++c) {
    const bool alpha = c == 3;
    const BlendEquation eq = alpha ? b.equation_alpha : b.equation_rgb;
    const float fs = blend_factor(alpha ? b.src_alpha : b.src_rgb, c, s, d, b.constant);
    const float fd = blend_factor(alpha ? b.dst_alpha : b.dst_rgb, c, s, d, b.constant);
    switch (eq) {
      case BlendEquation::kAdd: out[c] = s[c] * fs + d[c] * fd; break;
      case BlendEquation::kSubtract: out[c] = s[c] * fs - d[c] * fd; break;
      case BlendEquation::kReverseSubtract: out[c] = d[c] * fd - s[c] * fs; break;
      case BlendEquation::kMin: out[c] = std::min(s[c], d[c]); break;  // factors unused
      case BlendEquation::kMax: out[c] = std::max(s[c], d[c]); break;
    }
  }
  return out;
}

// glScissor with glEnable(GL_SCISSOR_TEST): only pixels x in [x, x + width), y in [y, y + height)
// are written.
struct ScissorState {
  bool enabled = false;
  int x = 0, y = 0, width = 0, height = 0;
};

// glColorMask: which channels are written.
struct ColorMask {
  bool r = true, g = true, b = true, a = true;
  bool all() const { return r && g && b && a; }
  glm::vec4 apply(const glm::vec4& written, const glm::vec4& old) const {
    return glm::vec4(r ? written.r : old.r, g ? written.g : old.g, b ? written.b : old.b, a ? written.a : old.a);
  }
};

}  // namespace tessref
