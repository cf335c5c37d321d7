// The offscreen render target, and a whole VS -> TCS -> TES -> FS draw into it.
#include <epoxy/gl.h>

#include <gtest/gtest.h>

#include "gl_fixture.h"
#include "glref/gl_error.h"
#include "glref/gl_program.h"
#include "glref/render_target.h"

namespace tessref::glref {
namespace {

TEST(RenderTarget, ClearsAndReadsBack) {
  TESSREF_REQUIRE_GL(ctx);
  RenderTarget rt(*ctx, {13, 7, {ColorFormat::kRgba8, ColorFormat::kRgba32F}, true});
  rt.clear({1.0f, 0.5f, 0.0f, 0.25f}, 0.75f);
  const auto c8 = rt.read_rgba8(0);
  ASSERT_EQ(c8.size(), 13u * 7u);
  EXPECT_EQ(c8[0], glm::u8vec4(255, 128, 0, 64));
  EXPECT_EQ(c8.back(), glm::u8vec4(255, 128, 0, 64));
  const auto cf = rt.read_rgba_float(1);
  EXPECT_EQ(cf[40], glm::vec4(1.0f, 0.5f, 0.0f, 0.25f));
  const auto d = rt.read_depth();
  EXPECT_EQ(d[12], 0.75f);
  const Framebuffer fb = rt.to_framebuffer();
  EXPECT_EQ(fb.width, 13);
  EXPECT_EQ(fb.aux.size(), 13u * 7u);
  EXPECT_THROW(rt.read_rgba8(2), GlError);
}

TEST(RenderTarget, RejectsBadSizesAndRestoresTheDefaultFramebuffer) {
  TESSREF_REQUIRE_GL(ctx);
  EXPECT_THROW(RenderTarget(*ctx, {0, 4}), GlError);
  EXPECT_THROW(RenderTarget(*ctx, {1 << 20, 4}), GlError);
  {
    RenderTarget rt(*ctx, {4, 4});
    rt.bind();
  }
  GLint bound = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
  EXPECT_NE(bound, 0);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
}

// A full-screen quad patch, tessellated with fractional levels and drawn with additive blending:
// every pixel must be covered exactly once (no crack, no overlap), depth follows z = x / 2.
TEST(RenderTarget, TessellatedFullScreenQuadCoversEveryPixelOnce) {
  TESSREF_REQUIRE_GL(ctx);
  const char* vs = R"(#version 450 core
void main() { gl_Position = vec4(float(gl_VertexID & 1) * 2.0 - 1.0, float(gl_VertexID >> 1) * 2.0 - 1.0, 0.0, 1.0); }
)";
  const char* tcs = R"(#version 450 core
layout(vertices = 4) out;
void main() {
  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
  gl_TessLevelOuter[0] = 7.3; gl_TessLevelOuter[1] = 3.9; gl_TessLevelOuter[2] = 12.2; gl_TessLevelOuter[3] = 5.5;
  gl_TessLevelInner[0] = 9.1; gl_TessLevelInner[1] = 4.4;
}
)";
  const char* tes = R"(#version 450 core
layout(quads, fractional_odd_spacing, ccw) in;
void main() {
  vec4 bottom = mix(gl_in[0].gl_Position, gl_in[1].gl_Position, gl_TessCoord.x);
  vec4 top = mix(gl_in[2].gl_Position, gl_in[3].gl_Position, gl_TessCoord.x);
  vec4 p = mix(bottom, top, gl_TessCoord.y);
  gl_Position = vec4(p.xy, p.x * 0.5, 1.0);
}
)";
  const char* fs = R"(#version 450 core
out vec4 color;
void main() { color = vec4(1.0, 0.0, 0.0, 1.0); }
)";
  Program program = link_program({{GL_VERTEX_SHADER, vs, "quad.vert"},
                                  {GL_TESS_CONTROL_SHADER, tcs, "quad.tesc"},
                                  {GL_TESS_EVALUATION_SHADER, tes, "quad.tese"},
                                  {GL_FRAGMENT_SHADER, fs, "quad.frag"}});
  const int w = 97, h = 61;
  RenderTarget rt(*ctx, {w, h, {ColorFormat::kRgba32F}, true});
  rt.clear(glm::vec4(0.0f), 1.0f);
  GLuint vao = 0;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  program.use();
  glPatchParameteri(GL_PATCH_VERTICES, 4);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glDrawArrays(GL_PATCHES, 0, 4);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDeleteVertexArrays(1, &vao);
  check_gl("drawing the tessellated quad");

  const auto color = rt.read_rgba_float();
  const auto depth = rt.read_depth();
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      ASSERT_EQ(color[i].r, 1.0f) << "pixel " << x << "," << y << " covered " << color[i].r << " times";
      const float x_ndc = (x + 0.5f) * 2.0f / w - 1.0f;
      ASSERT_NEAR(depth[i], 0.5f + 0.25f * x_ndc, 1e-5f) << "pixel " << x << "," << y;
    }
}

}  // namespace
}  // namespace tessref::glref
