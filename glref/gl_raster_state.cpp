#include "glref/gl_raster_state.h"

#include <epoxy/gl.h>

namespace tessref::glref {
namespace {

void enable(GLenum cap, bool on) { on ? glEnable(cap) : glDisable(cap); }

GLenum gl_depth_func(DepthFunc f) {
  switch (f) {
    case DepthFunc::kNever: return GL_NEVER;
    case DepthFunc::kLess: return GL_LESS;
    case DepthFunc::kEqual: return GL_EQUAL;
    case DepthFunc::kLessEqual: return GL_LEQUAL;
    case DepthFunc::kGreater: return GL_GREATER;
    case DepthFunc::kNotEqual: return GL_NOTEQUAL;
    case DepthFunc::kGreaterEqual: return GL_GEQUAL;
    case DepthFunc::kAlways: return GL_ALWAYS;
  }
  return GL_LESS;
}

GLenum gl_equation(BlendEquation e) {
  switch (e) {
    case BlendEquation::kAdd: return GL_FUNC_ADD;
    case BlendEquation::kSubtract: return GL_FUNC_SUBTRACT;
    case BlendEquation::kReverseSubtract: return GL_FUNC_REVERSE_SUBTRACT;
    case BlendEquation::kMin: return GL_MIN;
    case BlendEquation::kMax: return GL_MAX;
  }
  return GL_FUNC_ADD;
}

GLenum gl_factor(BlendFactor f) {
  static constexpr GLenum kFactors[] = {
      GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_DST_COLOR, GL_ONE_MINUS_DST_COLOR,
      GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA, GL_CONSTANT_COLOR,
      GL_ONE_MINUS_CONSTANT_COLOR, GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA, GL_SRC_ALPHA_SATURATE};
  return kFactors[int(f)];
}

}  // namespace

void apply_raster_state(const RasterState& s, int width, int height) {
  if (s.viewport) glViewport(s.viewport->x, s.viewport->y, s.viewport->width, s.viewport->height);
  else glViewport(0, 0, width, height);
  glDepthRange(s.depth_range_near, s.depth_range_far);
  enable(GL_DEPTH_TEST, s.depth_test);
  glDepthFunc(gl_depth_func(s.depth_func));
  glDepthMask(s.depth_write ? GL_TRUE : GL_FALSE);
  enable(GL_CULL_FACE, s.cull_back_faces || s.cull_front_faces);
  glCullFace(s.cull_back_faces && s.cull_front_faces ? GL_FRONT_AND_BACK : s.cull_front_faces ? GL_FRONT : GL_BACK);
  glFrontFace(s.front_face_cw ? GL_CW : GL_CCW);
  glPolygonMode(GL_FRONT_AND_BACK, s.polygon_mode == PolygonMode::kLine    ? GL_LINE
                                   : s.polygon_mode == PolygonMode::kPoint ? GL_POINT
                                                                           : GL_FILL);
  enable(GL_SCISSOR_TEST, s.scissor.enabled);
  if (s.scissor.enabled) glScissor(s.scissor.x, s.scissor.y, s.scissor.width, s.scissor.height);
  enable(GL_BLEND, s.blend.enabled);
  glBlendEquationSeparate(gl_equation(s.blend.equation_rgb), gl_equation(s.blend.equation_alpha));
  glBlendFuncSeparate(gl_factor(s.blend.src_rgb), gl_factor(s.blend.dst_rgb), gl_factor(s.blend.src_alpha),
                      gl_factor(s.blend.dst_alpha));
  glBlendColor(s.blend.constant.r, s.blend.constant.g, s.blend.constant.b, s.blend.constant.a);
  glColorMask(s.color_mask.r, s.color_mask.g, s.color_mask.b, s.color_mask.a);
  enable(GL_FRAMEBUFFER_SRGB, s.framebuffer_srgb);
  enable(GL_TEXTURE_CUBE_MAP_SEAMLESS, s.cube_map_seamless);
  enable(GL_DEPTH_CLAMP, s.depth_clamp);
  for (int i = 0; i < 8; ++i) enable(GL_CLIP_DISTANCE0 + GLenum(i), (s.clip_distances >> i) & 1u);
}

void reset_raster_state(int width, int height) { apply_raster_state(gl_initial_state(), width, height); }

}  // namespace tessref::glref
