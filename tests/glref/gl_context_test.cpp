// The headless context and the program helpers.
#include <epoxy/gl.h>

#include <gtest/gtest.h>

#include "gl_fixture.h"
#include "glref/gl_error.h"
#include "glref/gl_program.h"
#include "glref/shader_source.h"

namespace tessref::glref {
namespace {

TEST(GlContext, ReportsAGl45CoreContext) {
  TESSREF_REQUIRE_GL(ctx);
  EXPECT_FALSE(ctx->renderer().empty());
  EXPECT_NE(ctx->version().find("4."), std::string::npos) << ctx->version();
  GLint major = 0, minor = 0, mask = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
  EXPECT_GE(major * 10 + minor, 45);
  EXPECT_TRUE(mask & GL_CONTEXT_CORE_PROFILE_BIT);
  EXPECT_GE(ctx->max_tess_gen_level(), 64);
  RecordProperty("renderer", ctx->renderer());
}

TEST(GlContext, KeepsAFramebufferBound) {
  TESSREF_REQUIRE_GL(ctx);
  ctx->bind_default_framebuffer();
  GLint draw = 0, read = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw);
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
  EXPECT_NE(draw, 0);
  EXPECT_NE(read, 0);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
}

// A second (debug) context beside the shared one; destroying it leaves the shared one usable.
TEST(GlContext, SecondDebugContextComesAndGoes) {
  TESSREF_REQUIRE_GL(ctx);
  {
    GlContextOptions o;
    o.platform = ctx->platform();
    o.debug_context = true;
    GlContext second(o);
    GLint flags = 0;
    glGetIntegerv(GL_CONTEXT_FLAGS, &flags);
    EXPECT_TRUE(flags & GL_CONTEXT_FLAG_DEBUG_BIT);
    EXPECT_EQ(second.renderer(), ctx->renderer());
  }
  ctx->make_current();
  ctx->bind_default_framebuffer();
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
  check_gl("shared context after a second one");
}

TEST(GlContext, PlatformNamesRoundTrip) {
  for (EglPlatform p : {EglPlatform::Auto, EglPlatform::Surfaceless, EglPlatform::Device}) {
    EglPlatform q = EglPlatform::Auto;
    ASSERT_TRUE(parse(to_string(p), q));
    EXPECT_EQ(p, q);
  }
  EglPlatform q;
  EXPECT_FALSE(parse("x11", q));
}

TEST(GlError, CheckGlNamesTheCallAndTheCode) {
  TESSREF_REQUIRE_GL(ctx);
  check_gl("clean state");
  glEnable(0xFFFF);  // not a capability
  try {
    check_gl("glEnable(0xffff)");
    FAIL() << "expected GlError";
  } catch (const GlError& e) {
    EXPECT_NE(std::string(e.what()).find("glEnable(0xffff)"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("GL_INVALID_ENUM (0x500)"), std::string::npos) << e.what();
  }
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(GlProgram, CompileErrorCarriesStageNameAndInfoLog) {
  TESSREF_REQUIRE_GL(ctx);
  const ShaderStage bad{GL_VERTEX_SHADER, "#version 450 core\nvoid main() { gl_Position = nope; }\n",
                        "bad.vert"};
  try {
    link_program({bad});
    FAIL() << "expected GlError";
  } catch (const GlError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("vertex shader bad.vert"), std::string::npos) << what;
    EXPECT_NE(what.find("nope"), std::string::npos) << what;  // the driver's log names it
  }
}

TEST(GlProgram, LinkErrorCarriesTheLog) {
  TESSREF_REQUIRE_GL(ctx);
  const ShaderStage vs{GL_VERTEX_SHADER, "#version 450 core\nvoid main() { gl_Position = vec4(0); }\n", "a.vert"};
  // A transform-feedback varying that does not exist fails at link time.
  EXPECT_THROW(link_program({vs}, FeedbackVaryings{{"missing"}, true}), GlError);
}

TEST(GlProgram, LinksWithFeedbackVaryings) {
  TESSREF_REQUIRE_GL(ctx);
  const ShaderStage vs{GL_VERTEX_SHADER,
                       "#version 450 core\nout vec2 v;\nvoid main() { v = vec2(gl_VertexID); gl_Position = vec4(0); }\n",
                       "fb.vert"};
  Program p = link_program({vs}, FeedbackVaryings{{"v"}, true});
  EXPECT_TRUE(p);
  GLint n = 0;
  glGetProgramiv(p.id(), GL_TRANSFORM_FEEDBACK_VARYINGS, &n);
  EXPECT_EQ(n, 1);
  Program moved = std::move(p);
  EXPECT_FALSE(p);
  EXPECT_TRUE(moved);
}

TEST(ShaderSource, EmbeddedCaptureShadersExist) {
  for (const char* name : {"tpg_capture.vert", "tpg_capture.tesc", "tpg_capture.tese"})
    EXPECT_NE(shader_source(name).find("#version 450 core"), std::string::npos) << name;
  EXPECT_THROW(shader_source("no_such.glsl"), GlError);
}

TEST(ShaderSource, InjectsAfterTheVersionLine) {
  EXPECT_EQ(inject_after_version("// c\n#version 450 core\nvoid main(){}\n", "layout(x) in;"),
            "// c\n#version 450 core\nlayout(x) in;\nvoid main(){}\n");
  EXPECT_EQ(inject_after_version("#version 450 core", "A\n"), "#version 450 core\nA\n");
  EXPECT_THROW(inject_after_version("void main(){}\n", "A\n"), GlError);
}

}  // namespace
}  // namespace tessref::glref
