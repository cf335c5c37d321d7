// piglit .shader_test parsing: every section, every command kind, the error messages, and (when
// TESSREF_PIGLIT_SPEC points at piglit's tests/spec, see scripts/fetch-piglit.sh) every
// arb_tessellation_shader file.
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/error.h"
#include "piglit/shader_test_file.h"
#include "test_util.h"

namespace tessref {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using K = CommandKind;

// A file with a [require] section and the given [test] lines; the first command is on line 3.
ShaderTestFile with_test(const std::string& commands) {
  return parse_shader_test("[require]\n[test]\n" + commands, "t.shader_test");
}

// The one command of a [test] section, which must be on line 3.
TestCommand command(const std::string& line) {
  ShaderTestFile f = with_test(line + "\n");
  EXPECT_EQ(f.commands.size(), 1u) << line;
  if (f.commands.empty()) return {};
  EXPECT_EQ(f.commands[0].line, 3) << line;
  return f.commands[0];
}

// The InputError message for text, or "" if it parses.
std::string error(const std::string& text) {
  try {
    parse_shader_test(text, "t.shader_test");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string test_error(const std::string& commands) {
  return error("[require]\n[test]\n" + commands);
}

const char kSections[] = R"(# piglit ignores text before the first section
[require]
GLSL >= 1.50
GL_ARB_tessellation_shader

[vertex shader passthrough]

[vertex shader]
in vec4 v;
void main() { gl_Position = v; }

[tessellation control shader]
layout(vertices = 3) out;
void main() {}
[tessellation control shader]
float helper() { return 1.0; }
[tessellation evaluation shader]
layout(triangles) in;
[geometry shader]
// gs
[fragment shader]
void main() {}
[compute shader]
[fragment shader spirv]
; SPIR-V
[vertex program]
!!ARBvp1.0
[fragment shader specializations]
uint 0 3
[geometry layout]
input type GL_TRIANGLES
[test]
clear
)";

TEST(ShaderTestFile, SectionsKeepTheirSourceVerbatimWithTheirFirstLine) {
  const ShaderTestFile f = parse_shader_test(kSections, "dir/x.shader_test");
  EXPECT_EQ(f.file_name, "dir/x.shader_test");
  ASSERT_EQ(f.shaders.size(), 10u);
  struct Expected {
    ShaderStage stage;
    ShaderLanguage language;
    std::string source;
    int first_line;
  };
  using S = ShaderStage;
  using L = ShaderLanguage;
  const std::vector<Expected> expected = {
      {S::Vertex, L::Passthrough, "\n", 7},
      {S::Vertex, L::Glsl, "in vec4 v;\nvoid main() { gl_Position = v; }\n\n", 9},
      {S::TessControl, L::Glsl, "layout(vertices = 3) out;\nvoid main() {}\n", 13},
      {S::TessControl, L::Glsl, "float helper() { return 1.0; }\n", 16},
      {S::TessEvaluation, L::Glsl, "layout(triangles) in;\n", 18},
      {S::Geometry, L::Glsl, "// gs\n", 20},
      {S::Fragment, L::Glsl, "void main() {}\n", 22},
      {S::Compute, L::Glsl, "", 24},
      {S::Fragment, L::Spirv, "; SPIR-V\n", 25},
      {S::Vertex, L::ArbAssembly, "!!ARBvp1.0\n", 27},
  };
  for (std::size_t i = 0; i < expected.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(f.shaders[i].stage, expected[i].stage);
    EXPECT_EQ(f.shaders[i].language, expected[i].language);
    EXPECT_EQ(f.shaders[i].source, expected[i].source);
    EXPECT_EQ(f.shaders[i].first_line, expected[i].first_line);
  }
  ASSERT_EQ(f.other_sections.size(), 2u);
  EXPECT_EQ(f.other_sections[0].header, "[fragment shader specializations]");
  EXPECT_EQ(f.other_sections[0].text, "uint 0 3\n");
  EXPECT_EQ(f.other_sections[0].first_line, 29);
  EXPECT_EQ(f.other_sections[1].header, "[geometry layout]");
  EXPECT_FALSE(f.vertex_data);
  ASSERT_EQ(f.commands.size(), 1u);
  EXPECT_EQ(f.commands[0].kind, K::Clear);
  EXPECT_EQ(f.commands[0].line, 33);
}

TEST(ShaderTestFile, LastSectionRunsToTheEndWithoutANewline) {
  const ShaderTestFile f = parse_shader_test("[require]\n[fragment shader]\nvoid main() {}", "t");
  ASSERT_EQ(f.shaders.size(), 1u);
  EXPECT_EQ(f.shaders[0].source, "void main() {}");
  EXPECT_EQ(f.shaders[0].first_line, 3);
}

TEST(ShaderTestFile, TestSectionRunsToTheEndOfTheFile) {
  // Only [test] does not stop at a line starting with '[': it is always the last section.
  const ShaderTestFile f = with_test("clear\n[fragment shader]\n");
  ASSERT_EQ(f.commands.size(), 2u);
  EXPECT_EQ(f.commands[1].kind, K::Unknown);
  EXPECT_EQ(f.commands[1].text, "[fragment shader]");
  EXPECT_TRUE(f.shaders.empty());
}

TEST(ShaderTestFile, Requirements) {
  const ShaderTestFile f = parse_shader_test(R"([require]
GL COMPAT >= 3.2
GLSL >= 1.50
GL_ARB_tessellation_shader
!GL_ARB_foo   # a trailing comment
# a comment line
INT GL_MAX_TESS_CONTROL_ATOMIC_COUNTER_BUFFERS >= 1
GL_MAX_VARYING_COMPONENTS > 0x40
SIZE 250 125
SPIRV YES
depthbuffer
)",
                                             "t");
  const Requirements& r = f.requirements;
  ASSERT_TRUE(r.gl);
  EXPECT_EQ(r.gl->profile, Profile::Compat);
  EXPECT_EQ(r.gl->comparison, Comparison::GreaterEqual);
  EXPECT_EQ(r.gl->major, 3);
  EXPECT_EQ(r.gl->minor, 2);
  ASSERT_TRUE(r.glsl);
  EXPECT_EQ(r.glsl->profile, Profile::Any);
  EXPECT_EQ(r.glsl->major, 1);
  EXPECT_EQ(r.glsl->minor, 50);
  ASSERT_EQ(r.extensions.size(), 2u);
  EXPECT_EQ(r.extensions[0].name, "GL_ARB_tessellation_shader");
  EXPECT_FALSE(r.extensions[0].negated);
  EXPECT_EQ(r.extensions[1].name, "GL_ARB_foo");
  EXPECT_TRUE(r.extensions[1].negated);
  ASSERT_EQ(r.limits.size(), 2u);
  EXPECT_EQ(r.limits[0].name, "GL_MAX_TESS_CONTROL_ATOMIC_COUNTER_BUFFERS");
  EXPECT_EQ(r.limits[0].comparison, Comparison::GreaterEqual);
  EXPECT_EQ(r.limits[0].value, 1);
  EXPECT_EQ(r.limits[1].name, "GL_MAX_VARYING_COMPONENTS");
  EXPECT_EQ(r.limits[1].comparison, Comparison::Greater);
  EXPECT_EQ(r.limits[1].value, 64);
  ASSERT_TRUE(r.size);
  EXPECT_EQ(*r.size, (std::array<int, 2>{250, 125}));
  ASSERT_EQ(r.other.size(), 2u);
  EXPECT_EQ(r.other[0].line, 10);
  EXPECT_EQ(r.other[0].text, "SPIRV YES");
  EXPECT_EQ(r.other[1].line, 11);
  EXPECT_EQ(r.other[1].text, "depthbuffer");
}

TEST(ShaderTestFile, VersionMinorsAreNormalized) {
  auto versions = [](const std::string& lines) {
    return parse_shader_test("[require]\n" + lines, "t").requirements;
  };
  Requirements r = versions("GL CORE >= 4.00\nGLSL >= 4.5\n");
  EXPECT_EQ(r.gl->profile, Profile::Core);
  EXPECT_EQ(r.gl->major, 4);
  EXPECT_EQ(r.gl->minor, 0);
  EXPECT_EQ(r.glsl->major, 4);
  EXPECT_EQ(r.glsl->minor, 50);
  r = versions("GL ES >= 3.1\nGLSL ES >= 3.10\n");
  EXPECT_EQ(r.gl->profile, Profile::Es);
  EXPECT_EQ(r.gl->minor, 1);
  EXPECT_EQ(r.glsl->profile, Profile::Es);
  EXPECT_EQ(r.glsl->minor, 10);
  r = versions("GL >= 3.10\nGLSL < 1.30\n");
  EXPECT_EQ(r.gl->minor, 1);
  EXPECT_EQ(r.glsl->comparison, Comparison::Less);
}

TEST(ShaderTestFile, VertexDataColumns) {
  const ShaderTestFile f = parse_shader_test(R"([require]
[vertex data]
# header and rows may carry comments
vertex/float/2 color/float/vec3 i/int/1 u/uint/uvec2 d/double/dvec2 a[1]/float/1 m/float/mat2x3/1
-1.0 0x3f800000  0.5 .25 1e1  0xffffffff  0xffffffff -1  0.1 0x3ff0000000000000  7  1 2 3

 1    2    3 4 5  -2  3 4  -0.5 2  8  4 5 6  # second row
)",
                                             "t");
  ASSERT_TRUE(f.vertex_data);
  const VertexData& d = *f.vertex_data;
  EXPECT_EQ(d.first_line, 3);
  EXPECT_EQ(d.vertex_count, 2);
  ASSERT_EQ(d.columns.size(), 7u);
  const VertexColumn& vertex = d.columns[0];
  EXPECT_EQ(vertex.name, "vertex");
  EXPECT_EQ(vertex.data_type, DataType::Float);
  EXPECT_EQ(vertex.glsl_type.scalar, ScalarType::Float);
  EXPECT_EQ(vertex.glsl_type.columns, 1);
  EXPECT_EQ(vertex.glsl_type.rows, 2);
  EXPECT_THAT(vertex.values, ElementsAre(-1.0, 1.0, 1.0, 2.0));  // 0x3f800000 is 1.0f's bits
  const VertexColumn& color = d.columns[1];
  EXPECT_EQ(color.glsl_type.rows, 3);
  EXPECT_THAT(color.values, ElementsAre(0.5, 0.25, 10.0, 3, 4, 5));
  const VertexColumn& i = d.columns[2];
  EXPECT_EQ(i.data_type, DataType::Int);
  EXPECT_EQ(i.glsl_type.scalar, ScalarType::Int);
  EXPECT_THAT(i.values, ElementsAre(-1.0, -2.0));  // 0xffffffff is -1 as an int
  const VertexColumn& u = d.columns[3];
  EXPECT_EQ(u.glsl_type.scalar, ScalarType::Uint);
  EXPECT_EQ(u.glsl_type.rows, 2);
  EXPECT_THAT(u.values, ElementsAre(4294967295.0, 4294967295.0, 3, 4));  // -1 as a uint
  const VertexColumn& dv = d.columns[4];
  EXPECT_EQ(dv.data_type, DataType::Double);
  EXPECT_EQ(dv.glsl_type.scalar, ScalarType::Double);
  EXPECT_THAT(dv.values, ElementsAre(0.1, 1.0, -0.5, 2.0));  // doubles are not float-rounded
  const VertexColumn& a = d.columns[5];
  EXPECT_EQ(a.name, "a");
  EXPECT_EQ(a.array_index, 1);
  EXPECT_THAT(a.values, ElementsAre(7.0, 8.0));
  const VertexColumn& m = d.columns[6];
  EXPECT_EQ(m.glsl_type.columns, 2);
  EXPECT_EQ(m.glsl_type.rows, 3);
  EXPECT_EQ(m.matrix_column, 1);
  EXPECT_THAT(m.values, ElementsAre(1, 2, 3, 4, 5, 6));
}

TEST(ShaderTestFile, FloatColumnsAreFloatRounded) {
  const ShaderTestFile f = parse_shader_test("[require]\n[vertex data]\nv/float/1\n0.1\n", "t");
  EXPECT_EQ(f.vertex_data->columns[0].values[0], static_cast<double>(0.1f));
}

TEST(ShaderTestFile, ClearAndPatchParameters) {
  TestCommand c = command("clear color 0.1 0.2 0.3 0.4");
  EXPECT_EQ(c.kind, K::ClearColor);
  EXPECT_THAT(c.numbers, ElementsAre(0.1f, 0.2f, 0.3f, 0.4f));
  EXPECT_EQ(command("clear").kind, K::Clear);
  c = command("patch parameter vertices 4");
  EXPECT_EQ(c.kind, K::PatchVertices);
  EXPECT_THAT(c.numbers, ElementsAre(4));
  c = command("patch parameter default level outer 1 2 3 4.5");
  EXPECT_EQ(c.kind, K::PatchDefaultOuterLevel);
  EXPECT_THAT(c.numbers, ElementsAre(1, 2, 3, 4.5));
  c = command("patch parameter default level inner 5 3");
  EXPECT_EQ(c.kind, K::PatchDefaultInnerLevel);
  EXPECT_THAT(c.numbers, ElementsAre(5, 3));
}

TEST(ShaderTestFile, Draws) {
  TestCommand c = command("draw arrays GL_PATCHES 0 6");
  EXPECT_EQ(c.kind, K::DrawArrays);
  EXPECT_THAT(c.words, ElementsAre("GL_PATCHES"));
  EXPECT_THAT(c.numbers, ElementsAre(0, 6, 1));
  c = command("draw arrays instanced GL_TRIANGLES 3 6 2");
  EXPECT_EQ(c.kind, K::DrawArrays);
  EXPECT_THAT(c.words, ElementsAre("GL_TRIANGLES"));
  EXPECT_THAT(c.numbers, ElementsAre(3, 6, 2));
  c = command("draw rect -1 -1 2 2");
  EXPECT_EQ(c.kind, K::DrawRect);
  EXPECT_FALSE(c.ortho);
  EXPECT_FALSE(c.patch);
  EXPECT_THAT(c.numbers, ElementsAre(-1, -1, 2, 2, 1));
  c = command("draw rect patch -0.5 -1 0.09 0.09");
  EXPECT_TRUE(c.patch);
  EXPECT_FALSE(c.ortho);
  EXPECT_THAT(c.numbers, ElementsAre(-0.5, -1, 0.09f, 0.09f, 1));
  c = command("draw rect ortho 0 0 250 250");
  EXPECT_TRUE(c.ortho);
  EXPECT_FALSE(c.patch);
  c = command("draw instanced rect ortho patch 3 10 10 20 30");
  EXPECT_EQ(c.kind, K::DrawRect);
  EXPECT_TRUE(c.ortho);
  EXPECT_TRUE(c.patch);
  EXPECT_THAT(c.numbers, ElementsAre(10, 10, 20, 30, 3));
  c = command("draw instanced rect 4 -1 -1 2 2");
  EXPECT_FALSE(c.ortho);
  EXPECT_THAT(c.numbers, ElementsAre(-1, -1, 2, 2, 4));
  EXPECT_EQ(command("draw rect tex 0 0 1 1 0 0 1 1").kind, K::Unknown);
}

TEST(ShaderTestFile, Uniforms) {
  TestCommand c = command("uniform vec4 expect 0 1 0.5 1");
  EXPECT_EQ(c.kind, K::Uniform);
  EXPECT_THAT(c.words, ElementsAre("vec4", "expect"));
  EXPECT_EQ(c.type.scalar, ScalarType::Float);
  EXPECT_EQ(c.type.columns, 1);
  EXPECT_EQ(c.type.rows, 4);
  EXPECT_THAT(c.numbers, ElementsAre(0, 1, 0.5, 1));
  c = command("uniform int index[2] -3");
  EXPECT_THAT(c.words, ElementsAre("int", "index[2]"));
  EXPECT_EQ(c.type.scalar, ScalarType::Int);
  EXPECT_THAT(c.numbers, ElementsAre(-3));
  c = command("uniform ivec2 i 0x10 0xffffffff");
  EXPECT_THAT(c.numbers, ElementsAre(16, -1));
  c = command("uniform uvec3 u 0xffffffff 7 010");  // a leading 0 is octal, as in piglit
  EXPECT_EQ(c.type.scalar, ScalarType::Uint);
  EXPECT_THAT(c.numbers, ElementsAre(4294967295.0, 7, 8));
  // Integers keep their low 32 bits; uints may end in 'u' (both occur in piglit's tests).
  EXPECT_THAT(command("uniform uvec2 u 0x1fffffffe 3u").numbers, ElementsAre(4294967294.0, 3));
  EXPECT_THAT(command("uniform int i 4294967297").numbers, ElementsAre(1));
  EXPECT_THAT(command("uniform uint u 0x7fffffff80000000").numbers, ElementsAre(2147483648.0));
  // Floats beyond float's range are inf, as strtof has them.
  EXPECT_THAT(command("uniform vec2 v 3.4e+42 -1e39").numbers,
              ElementsAre(std::numeric_limits<double>::infinity(),
                          -std::numeric_limits<double>::infinity()));
  c = command("uniform float f 0xbf800000");
  EXPECT_THAT(c.numbers, ElementsAre(-1.0));
  c = command("uniform bvec2 b 1 0");
  EXPECT_EQ(c.type.scalar, ScalarType::Bool);
  EXPECT_THAT(c.numbers, ElementsAre(1, 0));
  c = command("uniform double d 0.1");
  EXPECT_EQ(c.type.scalar, ScalarType::Double);
  EXPECT_THAT(c.numbers, ElementsAre(0.1));
  c = command("uniform dvec3 d 0x3ff0000000000000 2 3");
  EXPECT_THAT(c.numbers, ElementsAre(1, 2, 3));
  c = command("uniform mat2x3 m 1 2 3 4 5 6");
  EXPECT_EQ(c.type.columns, 2);
  EXPECT_EQ(c.type.rows, 3);
  EXPECT_THAT(c.numbers, ElementsAre(1, 2, 3, 4, 5, 6));
  c = command("uniform dmat4 m 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1");
  EXPECT_EQ(c.type.scalar, ScalarType::Double);
  EXPECT_EQ(c.type.columns, 4);
  EXPECT_EQ(c.type.rows, 4);
  EXPECT_EQ(c.numbers.size(), 16u);
  EXPECT_EQ(command("uniform mat3 m 1 2 3 4 5 6 7 8 9").numbers.size(), 9u);
  EXPECT_EQ(command("uniform int64_t big 1").kind, K::Unknown);
}

TEST(ShaderTestFile, Probes) {
  TestCommand c = command("probe all rgba 0.0 1.0 0.0 1.0");
  EXPECT_EQ(c.kind, K::ProbeAll);
  EXPECT_THAT(c.numbers, ElementsAre(0, 1, 0, 1));
  c = command("probe all rgb 1 0 0");
  EXPECT_EQ(c.kind, K::ProbeAll);
  EXPECT_THAT(c.numbers, ElementsAre(1, 0, 0));
  c = command("probe rgb 6 18 0.0 1.0 0.0");
  EXPECT_EQ(c.kind, K::Probe);
  EXPECT_FALSE(c.relative);
  EXPECT_THAT(c.numbers, ElementsAre(6, 18, 0, 1, 0));
  c = command("probe rgba 1 2 0 0 1 1");
  EXPECT_EQ(c.kind, K::Probe);
  EXPECT_THAT(c.numbers, ElementsAre(1, 2, 0, 0, 1, 1));
  c = command("relative probe rgba ( 0.25 , 0.75 ) (0,1,0,0.5)");
  EXPECT_EQ(c.kind, K::Probe);
  EXPECT_TRUE(c.relative);
  EXPECT_THAT(c.numbers, ElementsAre(0.25, 0.75, 0, 1, 0, 0.5));
  c = command("relative probe rgb (0.5, 0.5) (1.0, 0.0, 0.0)");
  EXPECT_THAT(c.numbers, ElementsAre(0.5, 0.5, 1, 0, 0));
  c = command("probe rect rgba (0, 1, 10, 20) (0.0, 1.0, 0.0, 1.0)");
  EXPECT_EQ(c.kind, K::ProbeRect);
  EXPECT_FALSE(c.relative);
  EXPECT_THAT(c.numbers, ElementsAre(0, 1, 10, 20, 0, 1, 0, 1));
  c = command("relative probe rect rgb (0.0  , 0.524, 0.476, 0.476) (0.0, 0.5, 0.0)");
  EXPECT_EQ(c.kind, K::ProbeRect);
  EXPECT_TRUE(c.relative);
  EXPECT_THAT(c.numbers, ElementsAre(0, 0.524f, 0.476f, 0.476f, 0, 0.5, 0));
  c = command("relative probe rect rgba (0.5, 0.0, 0.5, 0.5) (0.6, 0.5, 0.6, 0.5)");
  EXPECT_EQ(c.numbers.size(), 8u);
  EXPECT_EQ(command("relative probe rect rgba int (0, 0, 1, 1) (1, 2, 3, 4)").kind, K::Unknown);
  EXPECT_EQ(command("probe depth 0 0 1").kind, K::Unknown);
  c = command("tolerance 0.1 0.1 0 0.1");
  EXPECT_EQ(c.kind, K::Tolerance);
  EXPECT_THAT(c.numbers, ElementsAre(0.1f, 0.1f, 0, 0.1f));
  EXPECT_THAT(command("tolerance 0.05").numbers, ElementsAre(0.05f));
}

TEST(ShaderTestFile, PiglitIgnoresWordsAfterTheArguments) {
  // Both forms occur in piglit's tests: an rgb probe given four values, trailing comments.
  TestCommand c = command("relative probe rgb (0.5, 0.8) (1.0, 1.0, 1.0, 1.0) # clipped");
  EXPECT_EQ(c.kind, K::Probe);
  EXPECT_EQ(c.text, "relative probe rgb (0.5, 0.8) (1.0, 1.0, 1.0, 1.0)");
  EXPECT_THAT(c.numbers, ElementsAre(0.5, 0.8f, 1, 1, 1));
  EXPECT_THAT(command("probe all rgb 1 0 0 0").numbers, ElementsAre(1, 0, 0));
}

TEST(ShaderTestFile, AtomicCounters) {
  TestCommand c = command("atomic counters 2");
  EXPECT_EQ(c.kind, K::AtomicCounters);
  EXPECT_THAT(c.numbers, ElementsAre(2));
  c = command("atomic counter buffer 1 4");
  EXPECT_EQ(c.kind, K::AtomicCounterBuffer);
  EXPECT_THAT(c.numbers, ElementsAre(1, 4));
  c = command("atomic counter 1 2 0x10");
  EXPECT_EQ(c.kind, K::AtomicCounterSet);
  EXPECT_THAT(c.numbers, ElementsAre(1, 2, 16));
  c = command("probe atomic counter 0 == 16");
  EXPECT_EQ(c.kind, K::ProbeAtomicCounter);
  EXPECT_EQ(c.comparison, Comparison::Equal);
  EXPECT_THAT(c.numbers, ElementsAre(0, 16));
  c = command("probe atomic counter buffer 1 8 >= 3");
  EXPECT_EQ(c.kind, K::ProbeAtomicCounterBuffer);
  EXPECT_EQ(c.comparison, Comparison::GreaterEqual);
  EXPECT_THAT(c.numbers, ElementsAre(1, 8, 3));
}

TEST(ShaderTestFile, Textures) {
  TestCommand c =
      command("texture checkerboard 0 0 (32, 32) (0.0, 0.0, 1.0, 0.0) (0.0, 1.0, 0.0, 0.0)");
  EXPECT_EQ(c.kind, K::TextureCheckerboard);
  EXPECT_THAT(c.numbers, ElementsAre(0, 0, 32, 32, 0, 0, 1, 0, 0, 1, 0, 0));
  c = command("texture rgbw 1 (8, 4)");
  EXPECT_EQ(c.kind, K::TextureRgbw);
  EXPECT_THAT(c.numbers, ElementsAre(1, 8, 4));
  EXPECT_TRUE(c.words.empty());
  c = command("texture rgbw 0 (16, 16) GL_RGBA8");
  EXPECT_THAT(c.words, ElementsAre("GL_RGBA8"));
  EXPECT_EQ(command("texture rgbw 3D 0").kind, K::Unknown);
  EXPECT_EQ(command("texture miptree 0").kind, K::Unknown);
  c = command("texparameter 2D min nearest");
  EXPECT_EQ(c.kind, K::TexParameter);
  EXPECT_THAT(c.words, ElementsAre("2D", "min", "nearest"));
}

TEST(ShaderTestFile, StateAndListCommands) {
  TestCommand c = command("enable GL_CLIP_PLANE4");
  EXPECT_EQ(c.kind, K::Enable);
  EXPECT_THAT(c.words, ElementsAre("GL_CLIP_PLANE4"));
  c = command("disable GL_CLIP_PLANE0");
  EXPECT_EQ(c.kind, K::Disable);
  EXPECT_THAT(c.words, ElementsAre("GL_CLIP_PLANE0"));
  c = command("clip plane 3 0 -1 0 7.5");
  EXPECT_EQ(c.kind, K::ClipPlane);
  EXPECT_THAT(c.numbers, ElementsAre(3, 0, -1, 0, 7.5));
  c = command("ortho");
  EXPECT_EQ(c.kind, K::Ortho);
  EXPECT_TRUE(c.numbers.empty());
  c = command("ortho 0 1 0 1");
  EXPECT_THAT(c.numbers, ElementsAre(0, 1, 0, 1));
  c = command("newlist GL_COMPILE_AND_EXECUTE");
  EXPECT_EQ(c.kind, K::NewList);
  EXPECT_THAT(c.words, ElementsAre("GL_COMPILE_AND_EXECUTE"));
  EXPECT_EQ(command("endlist").kind, K::EndList);
  EXPECT_EQ(command("calllist").kind, K::CallList);
  EXPECT_EQ(command("deletelist").kind, K::DeleteList);
  EXPECT_EQ(command("link error").kind, K::LinkError);
  EXPECT_EQ(command("link success").kind, K::LinkSuccess);
  EXPECT_EQ(command("ssbo 2 64").kind, K::SsboSize);
  EXPECT_EQ(command("ssbo 2 64").numbers, (std::vector<double>{2, 64}));
  const TestCommand sub = command("ssbo 0 subdata float 8 1.5 -2");
  EXPECT_EQ(sub.kind, K::SsboSubData);
  EXPECT_EQ(sub.numbers, (std::vector<double>{0, 8, 1.5, -2}));
  const TestCommand probe = command("probe ssbo uint 1 12 >= 42");
  EXPECT_EQ(probe.kind, K::ProbeSsbo);
  EXPECT_EQ(probe.numbers, (std::vector<double>{1, 12, 42}));
  EXPECT_EQ(probe.comparison, Comparison::GreaterEqual);
  EXPECT_EQ(command("ssbo 0 subdata int64 0 1").kind, K::Unknown);  // 64-bit integers: not run
}

TEST(ShaderTestFile, UnknownCommandsKeepTheirText) {
  const ShaderTestFile f =
      with_test("fb tex 2d 0\n  # comment\n\nclear depth 1.0\nblend func GL_ONE GL_ZERO\n");
  ASSERT_EQ(f.commands.size(), 3u);
  EXPECT_EQ(f.commands[0].kind, K::Unknown);
  EXPECT_EQ(f.commands[0].text, "fb tex 2d 0");
  EXPECT_EQ(f.commands[0].line, 3);
  EXPECT_TRUE(f.commands[0].numbers.empty());
  EXPECT_EQ(f.commands[1].kind, K::Unknown);
  EXPECT_EQ(f.commands[1].line, 6);
  EXPECT_EQ(f.commands[2].text, "blend func GL_ONE GL_ZERO");
  EXPECT_EQ(f.commands[2].line, 7);
}

TEST(ShaderTestFile, CommandLinesAreFileLines) {
  const ShaderTestFile f = parse_shader_test(
      "[require]\r\nGLSL >= 1.50\r\n\r\n[test]\r\n# c\r\nclear\r\n\r\ndraw arrays GL_PATCHES 0 "
      "3\r\n",
      "t");
  ASSERT_EQ(f.commands.size(), 2u);
  EXPECT_EQ(f.commands[0].line, 6);
  EXPECT_EQ(f.commands[1].line, 8);
  EXPECT_EQ(f.commands[1].text, "draw arrays GL_PATCHES 0 3");
  EXPECT_EQ(f.requirements.glsl->minor, 50);
}

TEST(ShaderTestFile, Errors) {
  EXPECT_EQ(error("[require]\n[vertex shader]\n\n[fragment shadr]\n"),
            "t.shader_test:4: unknown section '[fragment shadr]'");
  EXPECT_EQ(error("[vertex shader]\n"), "t.shader_test:1: no [require] section");
  EXPECT_EQ(error("[require]\n[require]\n"), "t.shader_test:2: a second [require] section");
  EXPECT_EQ(error("[require]\nGLSL >= 1.5x\n"),
            "t.shader_test:2: expected 'GLSL [CORE|COMPAT|ES] >= MAJOR.MINOR'");
  EXPECT_EQ(error("[require]\nGL >= 3.2\nGL >= 4.0\n"),
            "t.shader_test:3: a second GL version requirement");
  EXPECT_EQ(error("[require]\nSIZE 10\n"), "t.shader_test:2: expected 'SIZE WIDTH HEIGHT'");
  EXPECT_EQ(error("[require]\nGL_MAX_FOO >= x\n"), "t.shader_test:2: expected 'GL_NAME OP VALUE'");
  EXPECT_EQ(error("[require]\n[vertex data]\nv/float/2\n1 2\n3\n"),
            "t.shader_test:5: vertex data row has 1 values, the header asks for 2");
  EXPECT_EQ(error("[require]\n[vertex data]\nv/float/1\n1.0x\n"),
            "t.shader_test:4: vertex data column 'v': expected a float, got '1.0x'");
  EXPECT_EQ(error("[require]\n[vertex data]\nv/int/1\n0x1g\n"),
            "t.shader_test:4: vertex data column 'v': expected an integer, got '0x1g'");
  EXPECT_EQ(error("[require]\n[vertex data]\nv/ubyte/1\n256\n"),
            "t.shader_test:4: vertex data column 'v': expected an unsigned byte, got '256'");
  EXPECT_EQ(error("[require]\n[vertex data]\nv/half/2\n"),
            "t.shader_test:3: vertex data column 'v/half/2': unknown data type 'half'");
  EXPECT_EQ(error("[require]\n[vertex data]\nv/float/vec5\n"),
            "t.shader_test:3: vertex data column 'v/float/vec5': unknown GLSL type 'vec5'");
  EXPECT_EQ(error("[require]\n[vertex data]\nv/float/5\n"),
            "t.shader_test:3: vertex data column 'v/float/5': the component count must be 1 to 4");
  EXPECT_EQ(error("[require]\n[vertex data]\nv/float\n"),
            "t.shader_test:3: vertex data column 'v/float': expected NAME/TYPE/GLSL_TYPE or "
            "NAME/TYPE/COUNT, optionally /MATRIX_COLUMN");
  EXPECT_EQ(error("[require]\n[vertex data]\nv/float/1\n[vertex data]\n"),
            "t.shader_test:4: a second [vertex data] section");
  EXPECT_EQ(test_error("clear color 0.1 0.1 x 1\n"),
            "t.shader_test:3: 'clear color': expected a float, got 'x'");
  EXPECT_EQ(test_error("\ndraw arrays GL_PATCHES 0\n"),
            "t.shader_test:4: 'draw arrays': expected an integer, got the end of the line");
  EXPECT_EQ(test_error("draw arrays GL_PATCH 0 3\n"),
            "t.shader_test:3: 'draw arrays': unknown primitive mode 'GL_PATCH'");
  EXPECT_EQ(test_error("patch parameter vertices 2.5\n"),
            "t.shader_test:3: 'patch parameter vertices': expected an integer, got '2.5'");
  EXPECT_EQ(test_error("uniform vec3 v 1 2\n"),
            "t.shader_test:3: 'uniform': expected a float, got the end of the line");
  EXPECT_EQ(test_error("uniform float f 1.0;\n"),
            "t.shader_test:3: 'uniform': expected a float, got '1.0;'");
  EXPECT_EQ(test_error("relative probe rgba 0.5 0.5 (1, 1, 1, 1)\n"),
            "t.shader_test:3: 'relative probe rgba': expected '(', got '0.5'");
  EXPECT_EQ(test_error("probe rect rgba (0.5, 0, 1, 1) (1, 1, 1, 1)\n"),
            "t.shader_test:3: 'probe rect rgba': expected an integer, got '0.5'");
  EXPECT_EQ(test_error("probe atomic counter 0 =< 1\n"),
            "t.shader_test:3: 'probe atomic counter': unknown comparison '=<'");
  EXPECT_EQ(test_error("tolerance 1 2\n"), "t.shader_test:3: 'tolerance': expected 1 or 4 values");
  EXPECT_EQ(test_error("enable\n"),
            "t.shader_test:3: 'enable': expected a capability, got the end of the line");
}

TEST(ShaderTestFile, LoadReadsTheFile) {
  test::TempDir dir;
  const auto path = dir.write("a.shader_test", "[require]\n[test]\nclear\n");
  const ShaderTestFile f = load_shader_test(path.string());
  EXPECT_EQ(f.file_name, path.string());
  ASSERT_EQ(f.commands.size(), 1u);
  try {
    load_shader_test((dir.path() / "missing.shader_test").string());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("missing.shader_test: cannot read the file"));
  }
}

// Every arb_tessellation_shader file of piglit parses, with no Unknown command.
TEST(ShaderTestFile, PiglitTessellationTestsParse) {
  const char* spec = std::getenv("TESSREF_PIGLIT_SPEC");
  if (spec == nullptr || *spec == '\0')
    GTEST_SKIP() << "TESSREF_PIGLIT_SPEC is not set (export "
                    "TESSREF_PIGLIT_SPEC=$(scripts/fetch-piglit.sh | tail -n1))";
  const std::filesystem::path root = std::filesystem::path(spec) / "arb_tessellation_shader";
  ASSERT_TRUE(std::filesystem::is_directory(root)) << root;
  int files = 0, tes_files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".shader_test") continue;
    ++files;
    ShaderTestFile f;
    try {
      f = load_shader_test(entry.path().string());
    } catch (const InputError& e) {
      ADD_FAILURE() << e.what();
      continue;
    }
    for (const TestCommand& c : f.commands)
      EXPECT_NE(c.kind, K::Unknown) << entry.path().string() << ":" << c.line << ": " << c.text;
    for (const ShaderSection& s : f.shaders) {
      if (s.stage == ShaderStage::TessEvaluation) {
        ++tes_files;
        break;
      }
    }
  }
  // Debian bookworm's piglit (0~git20220119) has 116 files, 115 with a TES.
  EXPECT_GE(files, 100);
  EXPECT_GE(tes_files, 100);
}

}  // namespace
}  // namespace tessref
