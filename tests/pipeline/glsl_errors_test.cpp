// Bad shaders and bad values never crash or hang: each ends with its message (compile and link
// errors at the user's file and line, unsupported constructs by name, runaway shaders with the
// stage, patch and invocation) or with GL's defined result (clamped indices, discarded patches,
// clamped levels). Through the shader-test runner (piglit/shader_test_runner.h) on piglit-format
// text, through compile_program, and through the `tessref shader-test` command line.
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/parallel.h"
#include "piglit/shader_test_file.h"
#include "piglit/shader_test_runner.h"
#include "shader/glsl_compile.h"
#include "test_util.h"

namespace tessref {
namespace {

using ::testing::AllOf;
using ::testing::AnyOf;
using ::testing::HasSubstr;
using ::testing::StartsWith;
using test::TempDir;

// Runs piglit-format text as `tessref shader-test` would (two threads).
ShaderTestResult run_text(const std::string& text, const std::string& name = "e.shader_test",
                          std::uint64_t max_instructions = 100'000) {
  ShaderTestOptions options;
  options.limits.max_instructions = max_instructions;
  const Parallel parallel(2);
  return run_shader_test(parse_shader_test(text, name), parallel, options);
}

// The 1-based line of the first line of `text` containing `marker`.
int line_of(const std::string& text, const std::string& marker) {
  std::istringstream in(text);
  int n = 0;
  for (std::string line; std::getline(in, line);) {
    ++n;
    if (line.find(marker) != std::string::npos) return n;
  }
  ADD_FAILURE() << "no line contains '" << marker << "'";
  return -1;
}

std::string str(int n) { return std::to_string(n); }

::testing::AssertionResult passed(const ShaderTestResult& r) {
  if (r.verdict == Verdict::Pass) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << to_string(r.verdict) << ": " << r.reason;
}

// ---------------------------------------------------------------------------------------------
// Building blocks: a window-filling quad patch ("draw rect patch -1 -1 2 2": four vertices,
// (x, y), (x + w, y), (x, y + h), (x + w, y + h)), tessellated as quads.

const char* kRequire = "[require]\nGLSL >= 1.50\nGL_ARB_tessellation_shader\n\n";

const char* kVertex = R"([vertex shader]
in vec4 piglit_vertex;
void main() { gl_Position = piglit_vertex; }

)";

const char* kControl = R"([tessellation control shader]
#extension GL_ARB_tessellation_shader : require
layout(vertices = 4) out;
void main() {
  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
  gl_TessLevelOuter = float[4](4.0, 4.0, 4.0, 4.0);
  gl_TessLevelInner = float[2](4.0, 4.0);
}

)";

// A tessellation evaluation shader's first lines; the file adds its main().
const char* kEvaluationHead = R"([tessellation evaluation shader]
#extension GL_ARB_tessellation_shader : require
layout(quads, equal_spacing) in;
vec4 corner_mix() {
  vec4 a = mix(gl_in[0].gl_Position, gl_in[1].gl_Position, gl_TessCoord.x);
  vec4 b = mix(gl_in[2].gl_Position, gl_in[3].gl_Position, gl_TessCoord.x);
  return mix(a, b, gl_TessCoord.y);
}
)";

const char* kEvaluation = R"([tessellation evaluation shader]
#extension GL_ARB_tessellation_shader : require
layout(quads, equal_spacing) in;
void main() {
  vec4 a = mix(gl_in[0].gl_Position, gl_in[1].gl_Position, gl_TessCoord.x);
  vec4 b = mix(gl_in[2].gl_Position, gl_in[3].gl_Position, gl_TessCoord.x);
  gl_Position = mix(a, b, gl_TessCoord.y);
}

)";

const char* kGreen = R"([fragment shader]
void main() { gl_FragColor = vec4(0.0, 1.0, 0.0, 1.0); }

)";

const char* kDrawGreen = R"([test]
clear color 0.2 0.2 0.2 0.2
clear
draw rect patch -1 -1 2 2
probe all rgba 0.0 1.0 0.0 1.0
)";

// Four quad patches of four vertices each, all covering the window; "draw arrays" draws them.
const char* kFourPatches = R"([vertex data]
piglit_vertex/float/2
-1 -1
 1 -1
-1  1
 1  1
-1 -1
 1 -1
-1  1
 1  1
-1 -1
 1 -1
-1  1
 1  1
-1 -1
 1 -1
-1  1
 1  1

)";

TEST(GlslErrors, TheBuildingBlocksDrawAGreenWindow) {
  EXPECT_TRUE(passed(run_text(std::string(kRequire) + kVertex + kControl + kEvaluation + kGreen + kDrawGreen)));
}

// ---------------------------------------------------------------------------------------------
// Compile errors: the .shader_test file and its line (a section's first line is its offset)

TEST(GlslErrors, CompileErrorNamesTheFileAndTheLineInTheShaderTest) {
  const std::string text = std::string(kRequire) + kVertex + kControl + kEvaluationHead + R"(void main() {
  vec4 p = corner_mix();
  gl_Position = p * undeclared_scale;
}

)" + kGreen + kDrawGreen;
  const ShaderTestResult r = run_text(text, "syntax.shader_test");
  EXPECT_EQ(r.verdict, Verdict::Fail);
  EXPECT_EQ(r.reason, "syntax.shader_test:" + str(line_of(text, "undeclared_scale")) +
                          ": error: 'undeclared_scale' : undeclared identifier");
  EXPECT_EQ(line_of(text, "undeclared_scale"), 28);  // the file's line; the section's 10th
}

TEST(GlslErrors, SyntaxErrorNamesTheFileAndTheLine) {
  const std::string text = std::string(kRequire) + kVertex + kControl + kEvaluation + R"([fragment shader]
uniform vec4 tint;
void main() {
  vec4 c = tint * 2.0
  gl_FragColor = c;
}

)" + kDrawGreen;
  const ShaderTestResult r = run_text(text, "semicolon.shader_test");
  EXPECT_EQ(r.verdict, Verdict::Fail);
  // glslang notices the missing ';' at the next token, on the line after the statement.
  EXPECT_THAT(r.reason, StartsWith("semicolon.shader_test:" + str(line_of(text, "gl_FragColor = c;")) + ": error: "));
  EXPECT_THAT(r.reason, HasSubstr("syntax error"));
}

TEST(GlslErrors, ErrorsInSeveralSectionsAreAllReportedAtTheirLines) {
  const std::string text = std::string(kRequire) + R"([vertex shader]
in vec4 piglit_vertex;
void main() { gl_Position = piglit_vertex + missing_offset; }

)" + kControl + kEvaluation + R"([fragment shader]
void main() {
  gl_FragColor = no_such_function(1.0);
}

)" + kDrawGreen;
  const ShaderTestResult r = run_text(text, "two.shader_test");
  EXPECT_EQ(r.verdict, Verdict::Fail);
  EXPECT_THAT(r.reason, AllOf(HasSubstr("two.shader_test:" + str(line_of(text, "missing_offset")) +
                                        ": error: 'missing_offset' : undeclared identifier"),
                              HasSubstr("two.shader_test:" + str(line_of(text, "no_such_function")) +
                                        ": error: 'no_such_function' : no matching overloaded function found")));
}

// ---------------------------------------------------------------------------------------------
// Link errors name both stages and the variable

TEST(GlslErrors, EvaluationInputWithoutControlOutputIsALinkError) {
  const std::string text = std::string(kRequire) + kVertex + kControl + kEvaluationHead + R"(in vec4 bend[];
void main() {
  gl_Position = corner_mix() + bend[0];
}

)" + kGreen + kDrawGreen;
  const ShaderTestResult r = run_text(text, "link.shader_test");
  EXPECT_EQ(r.verdict, Verdict::Fail);
  EXPECT_EQ(r.reason, "link.shader_test:" + str(line_of(text, "+ bend[0]")) +
                          ": error: link error: tessellation evaluation shader input 'bend' has no matching "
                          "output in the tessellation control shader");
}

TEST(GlslErrors, TypeMismatchBetweenControlAndEvaluationIsALinkError) {
  const std::string text = std::string(kRequire) + kVertex + R"([tessellation control shader]
layout(vertices = 4) out;
out vec3 offset[];
void main() {
  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
  offset[gl_InvocationID] = vec3(0.0);
  gl_TessLevelOuter = float[4](4.0, 4.0, 4.0, 4.0);
  gl_TessLevelInner = float[2](4.0, 4.0);
}

)" + kEvaluationHead + R"(in vec4 offset[];
void main() {
  gl_Position = corner_mix() + offset[0];
}

)" + kGreen + kDrawGreen;
  const ShaderTestResult r = run_text(text, "type.shader_test");
  EXPECT_EQ(r.verdict, Verdict::Fail);
  EXPECT_EQ(r.reason, "type.shader_test:" + str(line_of(text, "+ offset[0]")) +
                          ": error: link error: tessellation evaluation shader input 'offset' is vec4 but the "
                          "tessellation control shader output 'offset' (type.shader_test:" +
                          str(line_of(text, "offset[gl_InvocationID] =")) + ") is vec3");
}

TEST(GlslErrors, VertexToControlMismatchNamesBothStages) {
  const std::string text = std::string(kRequire) + R"([vertex shader]
in vec4 piglit_vertex;
out float weight;
void main() { gl_Position = piglit_vertex; weight = 1.0; }

[tessellation control shader]
layout(vertices = 4) out;
in int weight[];
void main() {
  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position * float(weight[0]);
  gl_TessLevelOuter = float[4](4.0, 4.0, 4.0, 4.0);
  gl_TessLevelInner = float[2](4.0, 4.0);
}

)" + kEvaluation + kGreen + kDrawGreen;
  const ShaderTestResult r = run_text(text, "vs.shader_test");
  EXPECT_EQ(r.verdict, Verdict::Fail);
  EXPECT_EQ(r.reason, "vs.shader_test:" + str(line_of(text, "float(weight[0])")) +
                          ": error: link error: tessellation control shader input 'weight' is int but the "
                          "vertex shader output 'weight' (vs.shader_test:" + str(line_of(text, "weight = 1.0")) +
                          ") is float");
}

// ---------------------------------------------------------------------------------------------
// Unsupported constructs are named

// A geometry shader runs in shader tests: a pass-through one draws the rectangle, one that
// emits no complete primitive draws nothing.
TEST(GlslErrors, GeometryShadersRunInShaderTests) {
  const char* through = R"([geometry shader]
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
void main() { for (int i = 0; i < 3; ++i) { gl_Position = gl_in[i].gl_Position; EmitVertex(); } }

)";
  const char* probe = "[test]\nclear color 0.2 0.2 0.2 0.2\nclear\ndraw rect -1 -1 2 2\nprobe all rgba 0.0 1.0 0.0 1.0\n";
  EXPECT_EQ(run_text(std::string(kRequire) + kVertex + through + kGreen + probe, "through.shader_test").verdict, Verdict::Pass);
  const char* single = R"([geometry shader]
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
void main() { gl_Position = gl_in[0].gl_Position; EmitVertex(); }

)";
  const ShaderTestResult r = run_text(std::string(kRequire) + kVertex + single + kGreen + probe, "single.shader_test");
  EXPECT_EQ(r.verdict, Verdict::Fail);
  EXPECT_NE(r.reason.find("expected (0, 255, 0, 255), observed (51, 51, 51, 51)"), std::string::npos) << r.reason;
}

// A file that asks for a core context refuses the compatibility profile's state by name. Without
// that (shader_runner's compatibility context), the matrices and gl_Vertex are fed: the identity
// matrix draws the rectangle; a file that needs secondary colours is skipped before anything is
// compiled.
TEST(GlslErrors, CompatibilityStateIsRefusedByNameInACoreContext) {
  const std::string body = R"([vertex shader]
in vec4 piglit_vertex;
void main() {
  gl_Position = gl_ModelViewProjectionMatrix * piglit_vertex;
}

)" + std::string(kControl) + kEvaluation + kGreen + kDrawGreen;
  const std::string core = "[require]\nGL CORE >= 4.0\nGLSL >= 1.50\n\n" + body;
  const ShaderTestResult r = run_text(core, "compat.shader_test");
  EXPECT_EQ(r.verdict, Verdict::Fail);
  EXPECT_EQ(r.reason, "compat.shader_test:" + str(line_of(core, "gl_ModelViewProjectionMatrix")) +
                          ": error: 'gl_ModelViewProjectionMatrix' is compatibility-profile fixed-function "
                          "state, which tessref does not support; pass the matrix as a uniform instead");
  const ShaderTestResult fed = run_text(std::string(kRequire) + body, "fed.shader_test");
  EXPECT_EQ(fed.verdict, Verdict::Pass) << fed.reason;
  std::string back = body;
  back.insert(back.find("\n}"), "\n  gl_BackColor = vec4(1.0);");
  const ShaderTestResult skipped = run_text("[require]\nGL COMPAT >= 3.1\nGLSL >= 1.50\n\n" + back);
  EXPECT_EQ(skipped.verdict, Verdict::Skip);
  EXPECT_EQ(skipped.reason,
            "gl_BackColor (compatibility profile: tessref feeds gl_Vertex, the matrices and the front colours only)");
}

TEST(GlslErrors, RuntimeSizedShaderStorageBlockIsRefusedByName) {
  const std::string text = std::string(kRequire) + kVertex + kControl + kEvaluationHead + R"(layout(std430, binding = 0) buffer Points { vec4 points[]; };
void main() {
  gl_Position = corner_mix();
  points[0] = gl_Position;
}

)" + kGreen + kDrawGreen;
  const ShaderTestResult r = run_text(text, "ssbo.shader_test");
  EXPECT_EQ(r.verdict, Verdict::Fail);
  EXPECT_THAT(r.reason, HasSubstr("shader storage block 'Points' (binding 0) has a runtime-sized array"));
}

// A storage block no range is bound to is refused when the draw runs (GL leaves its reads
// undefined; piglit's runner binds no storage buffers).
TEST(GlslErrors, AnUnboundShaderStorageBlockIsRefusedByName) {
  const std::string text = std::string(kRequire) + kVertex + kControl + kEvaluationHead + R"(layout(std430, binding = 0) buffer Scale { float scale; };
void main() {
  gl_Position = corner_mix() * scale;
}

)" + kGreen + "[test]\ndraw rect patch -1 -1 2 2\n";
  const ShaderTestResult r = run_text(text, "ssbo_fixed.shader_test");
  EXPECT_EQ(r.verdict, Verdict::Fail);
  EXPECT_THAT(r.reason, HasSubstr("the shader storage block 'Scale' (binding 0) has no buffer range bound"));
}

TEST(GlslErrors, InstructionsOutsideTheExecutorAreRefusedByName) {
  struct Case {
    const char* name;
    const char* main;    // the evaluation shader's declarations and main()
    const char* marker;  // on the line the message names
    const char* what;
  };
  const std::vector<Case> cases = {
      {"carry", R"(uniform uint u;
void main() {
  uint carry;
  uint sum = uaddCarry(u, u, carry);
  gl_Position = corner_mix() * float(sum + carry);
}
)",
       "uaddCarry", "this instruction is outside the executor's scope (OpIAddCarry)"},
      {"cube image", R"(layout(rgba8, binding = 0) uniform imageCube img;
void main() {
  gl_Position = corner_mix();
  imageStore(img, ivec3(0), vec4(1.0));
}
)",
       "imageStore", "a cube map image (OpImageWrite)"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string text = std::string(kRequire) + kVertex + kControl + kEvaluationHead + c.main + "\n" + kGreen + kDrawGreen;
    const ShaderTestResult r = run_text(text, std::string(c.name) + ".shader_test");
    EXPECT_EQ(r.verdict, Verdict::Fail);
    EXPECT_EQ(r.reason, "tessellation evaluation shader: unsupported construct (line " +
                            str(line_of(text, c.marker)) + "): " + c.what);
  }
}

TEST(GlslErrors, SamplersAndLanguageFeaturesOutsideTessrefAreRefusedByName) {
  struct Case {
    const char* name;
    const char* main;  // the evaluation shader's declarations and main()
    std::string what;  // the reason, after "FILE:"
  };
  const std::vector<Case> cases = {
      {"multisample", "uniform sampler2DMS s;\nvoid main() { gl_Position = corner_mix() * texelFetch(s, ivec2(0), 1).x; }\n",
       "tessellation evaluation shader: unsupported construct (line 27): a sampler2DMS (tessref reads sampler1D, sampler2D, samplerCube, their Array and Shadow forms, sampler3D, sampler2DRect and sampler2DRectShadow, samplerBuffer, and the isampler and usampler forms of each, and the image forms of the same targets) (OpImageFetch)"},
      {"integer multisample array", "uniform usampler2DMSArray s;\nvoid main() { gl_Position = corner_mix() * float(texelFetch(s, ivec3(0), 1).x); }\n",
       "tessellation evaluation shader: unsupported construct (line 27): a usampler2DMSArray (tessref reads sampler1D, sampler2D, samplerCube, their Array and Shadow forms, sampler3D, sampler2DRect and sampler2DRectShadow, samplerBuffer, and the isampler and usampler forms of each, and the image forms of the same targets) (OpImageFetch)"},
      {"umul", "uniform uint u;\nvoid main() {\n  uint hi, lo;\n  umulExtended(u, u, hi, lo);\n  gl_Position = corner_mix() * float(hi + lo);\n}\n",
       "tessellation evaluation shader: unsupported construct (line 29): this instruction is outside the executor's scope (OpUMulExtended)"},
      {"subroutine", "subroutine float F();\nsubroutine(F) float one() { return 1.0; }\nsubroutine uniform F f;\nvoid main() { gl_Position = corner_mix() * f(); }\n",
       "subroutine.shader_test:26: error: 'subroutine' : not allowed when generating SPIR-V"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string text = std::string(kRequire) + kVertex + kControl + kEvaluationHead + c.main + "\n" + kGreen + kDrawGreen;
    const ShaderTestResult r = run_text(text, std::string(c.name) + ".shader_test");
    EXPECT_EQ(r.verdict, Verdict::Fail);
    EXPECT_THAT(r.reason, StartsWith(c.what));
  }
}

// docs/executor.md lists, under "Not supported (each refused with its name)", fragment outputs
// past GL_MAX_DRAW_BUFFERS (location 8 on) and interpolateAt*; more clip and cull distances than
// GL_MAX_COMBINED_CLIP_AND_CULL_DISTANCES fail to link.
TEST(GlslErrors, HighOutputsInterpolateAtAndTooManyDistancesAreRefusedByName) {
  struct Case {
    const char* name;
    std::string sections;  // evaluation main() and fragment shader
    std::string named;
  };
  const std::vector<Case> cases = {
      {"distances", "out float gl_ClipDistance[6];\nout float gl_CullDistance[3];\nvoid main() {\n"
                    "  gl_Position = corner_mix();\n  gl_ClipDistance[5] = 1.0;\n  gl_CullDistance[2] = 1.0;\n}\n\n" +
                        std::string(kGreen),
       "6 clip and 3 cull distances; GL_MAX_COMBINED_CLIP_AND_CULL_DISTANCES is 8"},
      {"location8", "void main() { gl_Position = corner_mix(); }\n\n[fragment shader]\nlayout(location = 8) out vec4 o;\n"
                    "void main() { o = vec4(0.0, 1.0, 0.0, 1.0); }\n\n",
       "location 8: past GL_MAX_DRAW_BUFFERS (8"},
      {"interpolate", "out vec4 c;\nvoid main() { gl_Position = corner_mix(); c = gl_Position; }\n\n[fragment shader]\n"
                      "in vec4 c;\nvoid main() { gl_FragColor = interpolateAtCentroid(c); }\n\n",
       "interpolateAtCentroid"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string text = std::string(kRequire) + kVertex + kControl + kEvaluationHead + c.sections +
                             "[test]\ndraw rect patch -1 -1 2 2\n";
    const ShaderTestResult r = run_text(text, std::string(c.name) + ".shader_test");
    EXPECT_EQ(r.verdict, Verdict::Fail);
    EXPECT_THAT(r.reason, HasSubstr(c.named));
  }
}

// Built-ins the pipeline does not provide read 0 before (gl_SubGroupSizeARB, where GL requires at
// least 1: issue 23); each is refused by name.
TEST(GlslErrors, BuiltInsThePipelineDoesNotProvideAreRefusedByName) {
  const struct {
    const char* name;
    std::string fragment;
    std::string named;
  } cases[] = {
      {"ballot", "#extension GL_ARB_shader_ballot : require\nvoid main() { gl_FragColor = vec4(float(gl_SubGroupSizeARB)); }\n",
       "'gl_SubGroupSizeARB' is a built-in input tessref's pipeline does not provide"},
      {"point_coord", "void main() { gl_FragColor = vec4(gl_PointCoord, 0.0, 1.0); }\n",
       "'gl_PointCoord' is a built-in input tessref's pipeline does not provide"},
      {"sample_id", "#extension GL_ARB_sample_shading : require\nvoid main() { gl_FragColor = vec4(float(gl_SampleID)); }\n",
       "'gl_SampleID' is a built-in input tessref's pipeline does not provide"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string text = std::string(kRequire) + kVertex + kControl + kEvaluation + "[fragment shader]\n" +
                             c.fragment + "\n[test]\ndraw rect patch -1 -1 2 2\n";
    const ShaderTestResult r = run_text(text, std::string(c.name) + ".shader_test");
    EXPECT_EQ(r.verdict, Verdict::Fail);
    EXPECT_THAT(r.reason, HasSubstr(c.named));
  }
}

// ---------------------------------------------------------------------------------------------
// Runaway shaders stop at the instruction budget, naming the stage, primitive and invocation

struct RunawayCase {
  const char* name;
  std::string program;  // the shader sections
  std::string where;    // the message's start after the command's line
};

// Each loop is infinite for one invocation only (n is odd, i stays even), so that the one named
// does not depend on the threads. The result feeds the output: an unused loop is dead code.
const std::string kLoop = R"(
    while (i != n) i += 2;
)";

void expect_runaway_stops(const RunawayCase& c) {
  SCOPED_TRACE(c.name);
  const std::string text = std::string(kRequire) + c.program + kFourPatches +
                           "[test]\nuniform int n 7\npatch parameter vertices 4\ndraw arrays GL_PATCHES 0 16\n"
                           "probe all rgba 0.0 1.0 0.0 1.0\n";
  const ShaderTestResult r = run_text(text, std::string(c.name) + ".shader_test", 20'000);
  EXPECT_EQ(r.verdict, Verdict::Fail);
  const std::string draw = str(line_of(text, "draw arrays"));
  EXPECT_THAT(r.reason, StartsWith(draw + ": " + c.where));
  EXPECT_THAT(r.reason, HasSubstr("instruction budget of 20000 exceeded (an infinite loop?); raise it with the "
                                  "scene key shaders.max_instructions (render, inspect: --set "
                                  "shaders.max_instructions=N) or shader-test's --max-shader-instructions"));
  EXPECT_THAT(r.reason, HasSubstr("[draw arrays GL_PATCHES 0 16]"));
  // With n even every loop ends: the same file passes.
  std::string finite = text;
  finite.replace(finite.find("uniform int n 7"), 15, "uniform int n 8");
  EXPECT_TRUE(passed(run_text(finite, std::string(c.name) + ".shader_test", 20'000)));
}

// A runaway loop in the vertex, control and evaluation shaders.
std::vector<RunawayCase> runaway_cases() {
  const std::string& loop = kLoop;
  return {
      {"vertex",
       std::string(R"([vertex shader]
in vec4 piglit_vertex;
uniform int n;
void main() {
  int i = 0;
  if (gl_VertexID == 6) {)") + loop + R"(  }
  gl_Position = piglit_vertex + vec4(float(i) * 0.0);
}

)" + kControl + kEvaluation + kGreen,
       "vertex shader, vertex 6"},
      {"control",
       std::string(kVertex) + R"([tessellation control shader]
layout(vertices = 4) out;
uniform int n;
void main() {
  int i = 0;
  if (gl_PrimitiveID == 1 && gl_InvocationID == 3) {)" + loop + R"(  }
  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position + vec4(float(i) * 0.0);
  gl_TessLevelOuter = float[4](4.0, 4.0, 4.0, 4.0);
  gl_TessLevelInner = float[2](4.0, 4.0);
}

)" + kEvaluation + kGreen,
       "tessellation control shader, patch 1, invocation 3"},
      {"evaluation",
       std::string(kVertex) + kControl + kEvaluationHead + R"(uniform int n;
void main() {
  int i = 0;
  if (gl_PrimitiveID == 2) {)" + loop + R"(  }
  gl_Position = corner_mix() + vec4(float(i) * 0.0);
}

)" + kGreen,
       "tessellation evaluation shader, patch 2, invocation 0"},
  };
}

TEST(GlslErrors, InfiniteLoopInEachStageStopsAtTheBudget) {
  for (const RunawayCase& c : runaway_cases()) expect_runaway_stops(c);
}

// The same loops with results nothing uses (issue 23): dead-code removal dropped them, and the
// invocations ended with no error, their outputs unwritten. Every loop now runs.
TEST(GlslErrors, InfiniteLoopsWhoseResultsNothingUsesStopAtTheBudgetToo) {
  for (RunawayCase c : runaway_cases()) {
    const std::string use = " + vec4(float(i) * 0.0)";
    ASSERT_NE(c.program.find(use), std::string::npos) << c.name;
    c.program.erase(c.program.find(use), use.size());
    expect_runaway_stops(c);
  }
}

// A fragment shader's run-time error is a failure with its message, not an abort: the tile's
// fragment sink flushes explicitly, never from a destructor.
TEST(GlslErrors, InfiniteLoopInTheFragmentShaderStopsAtTheBudget) {
  const std::string& loop = kLoop;
  expect_runaway_stops(
      {"fragment",
       std::string(kVertex) + kControl + kEvaluation + R"([fragment shader]
uniform int n;
void main() {
  int i = 0;
  if (gl_FragCoord.x == 10.5 && gl_FragCoord.y == 20.5) {)" + loop + R"(  }
  gl_FragColor = vec4(0.0, 1.0, 0.0, 1.0) + vec4(float(i) * 0.0);
}

)",
       "fragment shader, fragment (10, 20)"});
}

// ---------------------------------------------------------------------------------------------
// Defined results: robust indexing, integer division, tessellation levels

TEST(GlslErrors, OutOfRangeIndexInTheEvaluationShaderReadsTheClampedElement) {
  const std::string text = std::string(kRequire) + kVertex + kControl + kEvaluationHead + R"(uniform int idx;
uniform vec4 palette[3];
out vec4 color;
const vec4 fixed_colors[3] = vec4[3](vec4(1.0, 0.0, 0.0, 1.0), vec4(0.0, 1.0, 0.0, 1.0), vec4(0.0, 0.0, 1.0, 1.0));
void main() {
  gl_Position = corner_mix();
  color = fixed_colors[idx] * 0.5 + palette[idx] * 0.5;
}

[fragment shader]
in vec4 color;
void main() { gl_FragColor = color; }

[test]
clear color 0.2 0.2 0.2 0.2
uniform vec4 palette[0] 1.0 0.0 0.0 1.0
uniform vec4 palette[1] 0.0 1.0 0.0 1.0
uniform vec4 palette[2] 0.0 0.0 1.0 1.0
uniform int idx 1
clear
draw rect patch -1 -1 2 2
probe all rgba 0.0 1.0 0.0 1.0
# Past the end: the last element.
uniform int idx 3
clear
draw rect patch -1 -1 2 2
probe all rgba 0.0 0.0 1.0 1.0
uniform int idx 2147483647
clear
draw rect patch -1 -1 2 2
probe all rgba 0.0 0.0 1.0 1.0
# Before the start: the first.
uniform int idx -1
clear
draw rect patch -1 -1 2 2
probe all rgba 1.0 0.0 0.0 1.0
uniform int idx -2147483648
clear
draw rect patch -1 -1 2 2
probe all rgba 1.0 0.0 0.0 1.0
)";
  EXPECT_TRUE(passed(run_text(text, "index.shader_test")));
  // gl_in[] with a uniform index: GL leaves vertices past the patch undefined; clamped into
  // gl_in[gl_MaxPatchVertices] here, never a crash. Index -1000 reads gl_in[0] at (-1, -1).
  const std::string corners = std::string(kRequire) + kVertex + kControl + kEvaluationHead + R"(uniform int idx;
out vec4 color;
void main() {
  gl_Position = corner_mix();
  color = vec4(gl_in[idx].gl_Position.xy * 0.5 + 0.5, 0.0, 1.0);
}

[fragment shader]
in vec4 color;
void main() { gl_FragColor = color; }

[test]
uniform int idx 3
draw rect patch -1 -1 2 2
probe all rgba 1.0 1.0 0.0 1.0
uniform int idx -1000
draw rect patch -1 -1 2 2
probe all rgba 0.0 0.0 0.0 1.0
uniform int idx 1000
draw rect patch -1 -1 2 2
)";
  EXPECT_TRUE(passed(run_text(corners, "gl_in.shader_test")));
  // The probes do fail on a wrong colour.
  std::string wrong = text;
  wrong.replace(wrong.find("probe all rgba 0.0 0.0 1.0 1.0"), 30, "probe all rgba 0.0 1.0 0.0 1.0");
  const ShaderTestResult r = run_text(wrong, "index.shader_test");
  EXPECT_EQ(r.verdict, Verdict::Fail);
  EXPECT_THAT(r.reason, HasSubstr("expected (0, 255, 0, 255), observed (0, 0, 255, 255)"));
}

TEST(GlslErrors, IntegerDivisionByZeroInTheEvaluationShaderIsZero) {
  const std::string text = std::string(kRequire) + kVertex + kControl + kEvaluationHead + R"(uniform int num;
uniform int den;
out vec4 color;
void main() {
  gl_Position = corner_mix();
  int q = num / den;
  int m = num % den;
  color = vec4(q == 0 ? 1.0 : 0.0, m == 0 ? 1.0 : 0.0, q == num ? 1.0 : 0.0, 1.0);
}

[fragment shader]
in vec4 color;
void main() { gl_FragColor = color; }

[test]
uniform int num 7
uniform int den 0
draw rect patch -1 -1 2 2
probe all rgba 1.0 1.0 0.0 1.0
# INT_MIN / -1 wraps to INT_MIN (no trap); INT_MIN % -1 is 0.
uniform int num -2147483648
uniform int den -1
draw rect patch -1 -1 2 2
probe all rgba 0.0 1.0 1.0 1.0
)";
  EXPECT_TRUE(passed(run_text(text, "division.shader_test")));
}

// Doubles in an evaluation batch of one patch's 25 points (not a full 64): each lane's double moves
// whole (a double's lanes are interleaved over two rows).
TEST(GlslErrors, DoubleVectorsInTheEvaluationShader) {
  const std::string text = std::string(kRequire) + kVertex + kControl + kEvaluationHead + R"(out vec4 color;
void main() {
  gl_Position = corner_mix();
  double one = double(gl_TessCoord.x) * 0.0lf + 1.0lf;
  dvec2 g = dvec2(0.0lf, one);
  color = vec4(vec2(g), 0.0, 1.0);
}

[fragment shader]
in vec4 color;
void main() { gl_FragColor = color; }

)" + kDrawGreen;
  EXPECT_TRUE(passed(run_text(text, "doubles.shader_test")));
}

// Flat integers reach the fragment shader bit for bit, also those whose pattern is a float -0.0
// (INT_MIN) or a signalling NaN (0x7f800001), which interpolation arithmetic would change.
TEST(GlslErrors, FlatIntegersKeepEveryBitPattern) {
  const std::string text = std::string(kRequire) + kVertex + kControl + kEvaluationHead + R"(flat out ivec2 v;
uniform int a;
uniform int b;
void main() {
  gl_Position = corner_mix();
  v = ivec2(a, b);
}

[fragment shader]
flat in ivec2 v;
void main() {
  gl_FragColor = v == ivec2(int(0x80000000), 0x7f800001) ? vec4(0.0, 1.0, 0.0, 1.0) : vec4(1.0, 0.0, 0.0, 1.0);
}

[test]
uniform int a -2147483648
uniform int b 2139095041
clear color 0.2 0.2 0.2 0.2
clear
draw rect patch -1 -1 2 2
probe all rgba 0.0 1.0 0.0 1.0
)";
  EXPECT_TRUE(passed(run_text(text, "flat.shader_test")));
}

// The control shader's levels come from `mode` (uniform zero is 0.0, so that nothing folds).
std::string levels_file(const std::string& commands) {
  return std::string(kRequire) + kVertex + R"([tessellation control shader]
layout(vertices = 4) out;
uniform float zero;
uniform int mode;
void main() {
  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
  float nan = zero / zero, inf = 1.0 / zero;
  vec4 outer = vec4(4.0);
  vec2 inner = vec2(4.0);
  switch (mode) {
    case 0: break;
    case 1: outer = vec4(nan); break;
    case 2: outer.z = nan; break;                 // one relevant outer level
    case 3: outer = vec4(-1.0); break;
    case 4: outer.x = -zero; break;               // -0.0
    case 5: outer.y = -inf; break;
    case 6: inner = vec2(nan); break;             // inner levels never discard
    case 7: outer = vec4(inf); inner = vec2(inf); break;
    case 8: outer = vec4(1e30); inner = vec2(1e30); break;
    case 9: outer = vec4(64.0); inner = vec2(64.0); break;
    case 10: outer = vec4(-inf, 4.0, nan, 0.0); inner = vec2(-1.0, nan); break;
  }
  gl_TessLevelOuter = float[4](outer.x, outer.y, outer.z, outer.w);
  gl_TessLevelInner = float[2](inner.x, inner.y);
}

)" + kEvaluationHead + R"(layout(binding = 0, offset = 0) uniform atomic_uint points;
void main() {
  gl_Position = corner_mix();
  atomicCounterIncrement(points);
}

)" + kGreen + "[test]\nclear color 0.2 0.2 0.2 0.2\nuniform float zero 0\n" + commands;
}

std::string draw_mode(int mode, const std::string& probe) {
  return "uniform int mode " + str(mode) + "\natomic counters 1\nclear\ndraw rect patch -1 -1 2 2\n" + probe + "\n";
}

TEST(GlslErrors, NaNZeroAndNegativeOuterLevelsDiscardThePatch) {
  // GL 4.6, 11.2.2: a relevant outer level <= 0 or NaN discards the patch: nothing is drawn and
  // the evaluation shader never runs.
  const std::string discarded = "probe all rgba 0.2 0.2 0.2 0.2\nprobe atomic counter 0 == 0";
  std::string commands = draw_mode(0, "probe all rgba 0.0 1.0 0.0 1.0\nprobe atomic counter 0 == 25");
  for (int mode : {1, 2, 3, 4, 5, 10}) commands += draw_mode(mode, discarded);
  // NaN inner levels clamp to 1 (fmax), which a quad treats as 1 + epsilon: 2 segments with equal
  // spacing. The patch is drawn: 16 points on the rim (4 x 4 segments) and 1 inside.
  commands += draw_mode(6, "probe all rgba 0.0 1.0 0.0 1.0\nprobe atomic counter 0 == 17");
  EXPECT_TRUE(passed(run_text(levels_file(commands), "levels.shader_test")));
}

TEST(GlslErrors, InfiniteAndHugeLevelsAreClampedTo64) {
  // Equal spacing clamps to [1, 64]: inf and 1e30 tessellate as 64 does, a 65 x 65 grid of points.
  std::string commands;
  for (int mode : {9, 7, 8}) commands += draw_mode(mode, "probe all rgba 0.0 1.0 0.0 1.0\nprobe atomic counter 0 == 4225");
  EXPECT_TRUE(passed(run_text(levels_file(commands), "huge.shader_test")));
}

// ---------------------------------------------------------------------------------------------
// The command line: one verdict line per file, exit 1 when any failed, never a crash

using test::kBinary;
using test::CliRun;
using test::run_cli;

TEST(GlslErrors, CommandLineReportsEachFileAndExitsWithOne) {
  if (!std::filesystem::exists(kBinary)) GTEST_SKIP() << kBinary << " not built";
  TempDir dir;
  const std::string good_text = std::string(kRequire) + kVertex + kControl + kEvaluation + kGreen + kDrawGreen;
  const std::string loop_text = std::string(kRequire) + kVertex + kControl + kEvaluationHead + R"(uniform int n;
void main() {
  int i = 0;
  if (gl_PrimitiveID == 2)
    while (i != n) i += 2;
  gl_Position = corner_mix() + vec4(float(i) * 0.0);
}

)" + kGreen + kFourPatches + "[test]\nuniform int n 7\npatch parameter vertices 4\ndraw arrays GL_PATCHES 0 16\n";
  const std::string syntax_text = std::string(kRequire) + kVertex + kControl + kEvaluation +
                                  "[fragment shader]\nvoid main() {\n  gl_FragColor = vec4(1.0) +;\n}\n\n" + kDrawGreen;
  const std::string geometry_text = std::string(kRequire) + kVertex + kGreen +
                                    "[compute shader]\n#version 430\nlayout(local_size_x = 1) in;\nvoid main() {}\n\n"
                                    "[test]\ncompute 1 1 1\n";
  const auto good = dir.write("good.shader_test", good_text);
  const auto loop = dir.write("loop.shader_test", loop_text);
  const auto syntax = dir.write("syntax.shader_test", syntax_text);
  const auto geometry = dir.write("geometry.shader_test", geometry_text);
  const CliRun r = run_cli("shader-test --threads 2 --max-shader-instructions 5000 " + good.string() + " " +
                           loop.string() + " " + syntax.string() + " " + geometry.string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("pass: " + good.string() + "\n"));
  EXPECT_THAT(r.output, HasSubstr("fail: " + loop.string() + ": " + str(line_of(loop_text, "draw arrays")) +
                                  ": tessellation evaluation shader, patch 2, invocation 0"));
  EXPECT_THAT(r.output, HasSubstr("instruction budget of 5000 exceeded"));
  EXPECT_THAT(r.output, HasSubstr("fail: " + syntax.string() + ": " + syntax.string() + ":" +
                                  str(line_of(syntax_text, "vec4(1.0) +;")) + ": error: "));
  EXPECT_THAT(r.output, HasSubstr("skip: " + geometry.string() + ": a compute shader\n"));
  EXPECT_THAT(r.output, HasSubstr("1 passed, 2 failed, 1 skipped\n"));
  // Alone, the good file passes with exit code 0.
  const CliRun ok = run_cli("shader-test " + good.string());
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
  EXPECT_THAT(ok.output, HasSubstr("1 passed, 0 failed, 0 skipped\n"));
}

// draw arrays with a count far past the vertex data ended in std::bad_alloc; GL refuses a
// negative first or count (GL_INVALID_VALUE). Each fails its file at the draw's line.
TEST(GlslErrors, HugeAndNegativeDrawArgumentsFailAtTheirLine) {
  const std::string head = std::string(kRequire) + kVertex + kControl + kEvaluation + kGreen + kFourPatches +
                           "[test]\npatch parameter vertices 4\n";
  const std::string huge = head + "draw arrays GL_PATCHES 0 600000000\n";
  ShaderTestResult r = run_text(huge);
  EXPECT_EQ(r.verdict, Verdict::Fail);
  EXPECT_EQ(r.reason, str(line_of(huge, "draw arrays")) +
                          ": draw: 600000000 vertices to shade, more than tessref's limit of 4194304 per draw "
                          "(2432 MiB of shaded vertices) [draw arrays GL_PATCHES 0 600000000]");
  const std::string negative = head + "draw arrays GL_PATCHES -1 4\n";
  r = run_text(negative);
  EXPECT_EQ(r.verdict, Verdict::Fail);
  EXPECT_EQ(r.reason, str(line_of(negative, "draw arrays")) +
                          ": glDrawArrays: a negative first (-1) is GL_INVALID_VALUE [draw arrays GL_PATCHES -1 4]");
  r = run_text(head + "draw arrays GL_PATCHES 0 -4\n");
  EXPECT_THAT(r.reason, HasSubstr("glDrawArrays: a negative count (-4) is GL_INVALID_VALUE"));
  // Counts keep their low 32 bits, as piglit's int does: GL sees -1.
  r = run_text(head + "draw arrays GL_PATCHES 0 4294967295\n");
  EXPECT_THAT(r.reason, HasSubstr("glDrawArrays: a negative count (-1) is GL_INVALID_VALUE"));
  // A count within the data draws.
  EXPECT_TRUE(passed(run_text(head + "draw arrays GL_PATCHES 0 16\n")));
}

// GLSL 4.50 section 4.4.2.1: an output patch larger than GL_MAX_PATCH_VERTICES is a compile-time
// error; it reached the pipeline's internal check (exit 3 from render).
TEST(GlslErrors, OutputPatchPastGlMaxPatchVerticesFailsToCompile) {
  std::string control = kControl;
  control.replace(control.find("vertices = 4"), 12, "vertices = 33");
  const std::string text = std::string(kRequire) + kVertex + control + kEvaluation + kGreen + kDrawGreen;
  const ShaderTestResult r = run_text(text, "v33.shader_test");
  EXPECT_EQ(r.verdict, Verdict::Fail);
  EXPECT_EQ(r.reason, "v33.shader_test:" + str(line_of(text, "vertices = 33")) +
                          ": error: layout(vertices = 33) is more than GL_MAX_PATCH_VERTICES (32): an output patch "
                          "has 1 to 32 vertices");
  control = kControl;
  control.replace(control.find("vertices = 4"), 12, "vertices = 32");
  EXPECT_TRUE(passed(run_text(std::string(kRequire) + kVertex + control + kEvaluation + kGreen +
                              "[test]\ndraw rect patch -1 -1 2 2\n")));
}

// A missing file is bad input (exit 2), found before any file runs; it was a "fail" (exit 1).
TEST(GlslErrors, CommandLineRefusesAMissingFileWithTwo) {
  if (!std::filesystem::exists(kBinary)) GTEST_SKIP() << kBinary << " not built";
  TempDir dir;
  const auto good = dir.write("good.shader_test", std::string(kRequire) + kVertex + kControl + kEvaluation + kGreen +
                                                      kDrawGreen);
  const std::string missing = (dir.path() / "missing.shader_test").string();
  CliRun r = run_cli("shader-test " + good.string() + " " + missing);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(r.output, "tessref: error: " + missing + ": no such .shader_test file\n");
  r = run_cli("shader-test " + dir.path().string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr(dir.path().string() + ": not a regular file, not a .shader_test file"));
  // A huge draw is that file's failure (exit 1), with the message.
  const auto huge = dir.write("huge.shader_test", std::string(kRequire) + kVertex + kControl + kEvaluation + kGreen +
                                                      kFourPatches + "[test]\npatch parameter vertices 4\n"
                                                      "draw arrays GL_PATCHES 0 600000000\n");
  r = run_cli("shader-test " + huge.string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("fail: " + huge.string() + ": "));
  EXPECT_THAT(r.output, HasSubstr("600000000 vertices to shade, more than tessref's limit of 4194304 per draw"));
}

TEST(GlslErrors, CommandLineRefusesAZeroBudget) {
  if (!std::filesystem::exists(kBinary)) GTEST_SKIP() << kBinary << " not built";
  const CliRun r = run_cli("shader-test --max-shader-instructions 0 nothing.shader_test");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_LT(r.exit_code, 128) << "killed by a signal: " << r.output;
  EXPECT_THAT(r.output, HasSubstr("--max-shader-instructions"));
}

}  // namespace
}  // namespace tessref
