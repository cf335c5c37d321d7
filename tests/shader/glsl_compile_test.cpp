// The GLSL front-end: compile + link + legalize, the source rewrites, the error messages, and
// the project's own GLSL twins.
#include "shader/glsl_compile.h"
#include "shader/glsl_rewrite.h"
#include "shader/spirv_module.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <spirv/unified1/spirv.hpp>

#include <fstream>
#include <map>
#include <optional>
#include <sstream>

namespace tessref::shader {
namespace {

using ::testing::AllOf;
using ::testing::Contains;
using ::testing::HasSubstr;
using ::testing::Not;

// Just enough of a SPIR-V reader for the checks below.
struct Instruction {
  spv::Op op;
  std::vector<std::uint32_t> operands;
  std::string string(std::size_t first) const {  // a literal string starting at operand `first`
    std::string s;
    for (std::size_t i = first; i < operands.size(); ++i)
      for (int b = 0; b < 4; ++b) {
        const char c = static_cast<char>(operands[i] >> (8 * b));
        if (c == '\0') return s;
        s += c;
      }
    return s;
  }
};

struct Module {
  explicit Module(const std::vector<std::uint32_t>& words)
      : header(words.begin(), words.begin() + 5) {
    for (std::size_t i = 5; i < words.size();) {
      const std::uint32_t count = words[i] >> 16;
      instructions.push_back({static_cast<spv::Op>(words[i] & 0xffff),
                              {words.begin() + i + 1, words.begin() + i + count}});
      i += count;
    }
  }
  bool has(spv::Op op) const {
    for (const Instruction& i : instructions)
      if (i.op == op) return true;
    return false;
  }
  std::optional<std::uint32_t> id_named(const std::string& name) const {
    for (const Instruction& i : instructions)
      if (i.op == spv::Op::OpName && i.string(1) == name) return i.operands[0];
    return std::nullopt;
  }
  std::optional<std::uint32_t> location(const std::string& name) const {
    const auto id = id_named(name);
    for (const Instruction& i : instructions)
      if (id && i.op == spv::Op::OpDecorate && i.operands[0] == *id &&
          i.operands[1] == static_cast<std::uint32_t>(spv::DecorationLocation))
        return i.operands[2];
    return std::nullopt;
  }
  spv::ExecutionModel execution_model() const {
    for (const Instruction& i : instructions)
      if (i.op == spv::Op::OpEntryPoint) return static_cast<spv::ExecutionModel>(i.operands[0]);
    return spv::ExecutionModelMax;
  }
  // Every OpLine as "FILE:LINE".
  std::vector<std::string> lines() const {
    std::map<std::uint32_t, std::string> files;
    std::vector<std::string> out;
    for (const Instruction& i : instructions) {
      if (i.op == spv::Op::OpString) files[i.operands[0]] = i.string(1);
      if (i.op == spv::Op::OpLine)
        out.push_back(files[i.operands[0]] + ":" + std::to_string(i.operands[1]));
    }
    return out;
  }

  std::vector<std::uint32_t> header;
  std::vector<Instruction> instructions;
};

const CompiledStage& stage(const CompiledProgram& program, Stage s) {
  for (const CompiledStage& c : program.stages)
    if (c.stage == s) return c;
  throw std::runtime_error(std::string("no ") + stage_name(s));
}
Module module(const CompiledProgram& program, Stage s) { return Module(stage(program, s).spirv); }

// compile_program's CompileError message, or "" when it compiles.
std::string error_of(const std::vector<ShaderSource>& sources) {
  try {
    compile_program(sources);
  } catch (const CompileError& e) {
    return e.what();
  }
  return "";
}

const char* kVertex = R"(#version 450
layout(location = 0) in vec4 position;
out vec4 color;
out vec3 extra;
void main() {
  gl_Position = position;
  color = position * 0.5;
  extra = position.xyz;
}
)";

const char* kControl = R"(#version 450
layout(vertices = 3) out;
in vec4 color[];
in vec3 extra[];
out Data { vec4 color; vec3 extra; } tcs_out[];
patch out vec4 centre;
void main() {
  tcs_out[gl_InvocationID].color = color[gl_InvocationID];
  tcs_out[gl_InvocationID].extra = extra[gl_InvocationID];
  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
  centre = vec4(0.25);
  gl_TessLevelOuter = float[4](2.0, 2.0, 2.0, 1.0);
  gl_TessLevelInner = float[2](2.0, 1.0);
}
)";

const char* kEvaluation = R"(#version 450
layout(triangles, equal_spacing, ccw) in;
in Data { vec4 color; vec3 extra; } tes_in[];
patch in vec4 centre;
out vec3 extra;
out vec4 color;
vec4 blend(vec4 a, vec4 b, vec4 c) {
  return a * gl_TessCoord.x + b * gl_TessCoord.y + c * gl_TessCoord.z;
}
void main() {
  color = blend(tes_in[0].color, tes_in[1].color, tes_in[2].color) + centre;
  extra = tes_in[0].extra;
  gl_Position = blend(gl_in[0].gl_Position, gl_in[1].gl_Position, gl_in[2].gl_Position);
}
)";

const char* kFragment = R"(#version 450
in vec4 color;
in vec3 extra;
uniform float u_gain;
layout(location = 0) out vec4 out_color;
vec4 shade(vec4 c) {
  vec4 s = c * u_gain;
  return s;
}
void main() {
  out_color = shade(color) + vec4(extra, 0.0);
}
)";

std::vector<ShaderSource> pipeline_sources() {
  return {{Stage::Vertex, "p.vert", 1, kVertex},
          {Stage::TessControl, "p.tesc", 1, kControl},
          {Stage::TessEval, "p.tese", 1, kEvaluation},
          {Stage::Fragment, "p.frag", 1, kFragment}};
}

TEST(GlslCompile, EveryStageBecomesLegalizedSpirv) {
  const CompiledProgram program = compile_program(pipeline_sources());
  ASSERT_EQ(program.stages.size(), 4u);
  const std::map<Stage, spv::ExecutionModel> models = {
      {Stage::Vertex, spv::ExecutionModelVertex},
      {Stage::TessControl, spv::ExecutionModelTessellationControl},
      {Stage::TessEval, spv::ExecutionModelTessellationEvaluation},
      {Stage::Fragment, spv::ExecutionModelFragment}};
  std::vector<Stage> order;
  for (const CompiledStage& s : program.stages) {
    order.push_back(s.stage);
    const Module m(s.spirv);
    EXPECT_EQ(m.header[0], spv::MagicNumber);
    EXPECT_EQ(m.header[1], 0x00010000u) << "SPIR-V 1.0";
    EXPECT_EQ(m.execution_model(), models.at(s.stage));
    EXPECT_FALSE(m.has(spv::Op::OpFunctionCall)) << stage_name(s.stage);
    EXPECT_TRUE(s.rewrites.empty()) << s.rewrites.front();
  }
  EXPECT_EQ(order, (std::vector<Stage>{Stage::Vertex, Stage::TessControl, Stage::TessEval,
                                       Stage::Fragment}));
}

TEST(GlslCompile, KeepsNamesAndSourceLines) {
  const CompiledProgram program = compile_program(pipeline_sources());
  const Module fs = module(program, Stage::Fragment);
  for (const char* name : {"color", "extra", "out_color", "u_gain"})
    EXPECT_TRUE(fs.id_named(name)) << name;
  EXPECT_TRUE(fs.location("u_gain")) << "default-block uniforms get a location";
  // The inlined helper's multiply (line 7) and main's add (line 11) keep their lines.
  EXPECT_THAT(fs.lines(), Contains("p.frag:7"));
  EXPECT_THAT(fs.lines(), Contains("p.frag:11"));
  EXPECT_THAT(module(program, Stage::TessEval).lines(), Contains("p.tese:8"));
}

TEST(GlslCompile, LinesCountFromFirstLine) {
  std::vector<ShaderSource> sources = pipeline_sources();
  sources[3].first_line = 40;  // a piglit section starting at line 40 of its file
  EXPECT_THAT(module(compile_program(sources), Stage::Fragment).lines(), Contains("p.frag:50"));
}

TEST(GlslCompile, NoFloatingPointFolding) {
  // x + 0.0 is not x for x = -0.0: the add must survive legalization.
  const char* fragment = R"(#version 450
in vec4 color;
layout(location = 0) out vec4 out_color;
void main() { out_color = color + vec4(0.0); }
)";
  const CompiledProgram program = compile_program(
      {{Stage::Vertex, "p.vert", 1, kVertex}, {Stage::Fragment, "p.frag", 1, fragment}});
  EXPECT_TRUE(module(program, Stage::Fragment).has(spv::Op::OpFAdd));
}

TEST(GlslCompile, MatchingNamesShareLocationsAcrossStages) {
  const CompiledProgram program = compile_program(pipeline_sources());
  const Module vs = module(program, Stage::Vertex), tcs = module(program, Stage::TessControl),
               tes = module(program, Stage::TessEval), fs = module(program, Stage::Fragment);
  // VS -> TCS by variable name; TCS -> TES by block name (instance names differ); TES -> FS
  // with the declarations in another order.
  for (const char* name : {"color", "extra"}) {
    ASSERT_TRUE(vs.location(name)) << name;
    EXPECT_EQ(vs.location(name), tcs.location(name)) << name;
    EXPECT_EQ(tes.location(name), fs.location(name)) << name;
  }
  ASSERT_TRUE(tcs.location("tcs_out"));
  EXPECT_EQ(tcs.location("tcs_out"), tes.location("tes_in"));
  EXPECT_EQ(tcs.location("centre"), tes.location("centre"));
  // No two names share a location.
  EXPECT_NE(vs.location("color"), vs.location("extra"));
  EXPECT_NE(tcs.location("tcs_out"), tcs.location("centre"));
}

TEST(GlslCompile, ExplicitLocationsAreKeptAndNamesShareOne) {
  const char* vertex = R"(#version 450
layout(location = 0) out vec4 first;
out vec4 second;
layout(location = 3) out vec4 third;
void main() { gl_Position = vec4(0.0); first = second = third = vec4(1.0); }
)";
  const char* fragment = R"(#version 450
layout(location = 0) in vec4 first;
in vec4 second;
layout(location = 3) in vec4 third;
layout(location = 0) out vec4 out_color;
void main() { out_color = first + second + third; }
)";
  const CompiledProgram program = compile_program(
      {{Stage::Vertex, "p.vert", 1, vertex}, {Stage::Fragment, "p.frag", 1, fragment}});
  const Module vs = module(program, Stage::Vertex), fs = module(program, Stage::Fragment);
  EXPECT_EQ(fs.location("first"), 0u);
  EXPECT_EQ(fs.location("third"), 3u);
  // Matched by name on both sides: one location, clear of the explicit ones.
  EXPECT_EQ(vs.location("second"), fs.location("second"));
  EXPECT_NE(vs.location("second"), 0u);
  EXPECT_NE(vs.location("second"), 3u);
}

TEST(GlslCompile, BoolUniformsAreKept) {
  // glslang stores them in UniformConstant, which the SPIR-V validator refuses on its own.
  const char* fragment = R"(#version 450
in vec4 color;
uniform bool u_flag;
uniform bvec2 u_flags[2];
layout(location = 0) out vec4 out_color;
void main() { out_color = u_flag && u_flags[1].y ? color : vec4(0.0); }
)";
  const Module fs = module(compile_program({{Stage::Vertex, "b.vert", 1, kVertex},
                                            {Stage::Fragment, "b.frag", 1, fragment}}),
                           Stage::Fragment);
  EXPECT_TRUE(fs.location("u_flag"));
  EXPECT_TRUE(fs.location("u_flags"));
}

// ---------------------------------------------------------------------------------------------
// Rewrites

const char* kPassThroughVertex = R"(#version 150
in vec4 piglit_vertex;
void main() { gl_Position = piglit_vertex; }
)";

TEST(GlslCompile, FragColorBecomesAnOutputAtLocationZero) {
  const char* fragment = "#version 150\nvoid main() {\n  gl_FragColor = vec4(1.0);\n}\n";
  const CompiledProgram program = compile_program(
      {{Stage::Vertex, "t.vert", 1, kPassThroughVertex}, {Stage::Fragment, "t.frag", 1, fragment}});
  const CompiledStage& fs = stage(program, Stage::Fragment);
  EXPECT_THAT(fs.rewrites,
              Contains("t.frag:3: gl_FragColor written as 'layout(location = 0) out vec4 "
                       "tessref_FragColor'"));
  EXPECT_EQ(Module(fs.spirv).location("tessref_FragColor"), 0u);
}

TEST(GlslCompile, CommentsAreNotRewritten) {
  const char* fragment = R"(#version 450
// Unlike gl_FragColor, attribute and varying, texture2D() is not here.
/* #extension GL_ARB_tessellation_shader : require */
layout(location = 0) out vec4 out_color;
void main() { out_color = vec4(1.0); }
)";
  const CompiledProgram program = compile_program(
      {{Stage::Vertex, "t.vert", 1, kVertex}, {Stage::Fragment, "t.frag", 1, fragment}});
  EXPECT_TRUE(stage(program, Stage::Fragment).rewrites.empty());
}

TEST(GlslCompile, FragDataBecomesAnOutputArray) {
  const char* fragment = "#version 150\nvoid main() { gl_FragData[1] = vec4(1.0); }\n";
  const CompiledProgram program = compile_program(
      {{Stage::Vertex, "t.vert", 1, kPassThroughVertex}, {Stage::Fragment, "t.frag", 1, fragment}});
  EXPECT_THAT(stage(program, Stage::Fragment).rewrites,
              Contains(HasSubstr("t.frag:2: gl_FragData written as")));
  EXPECT_EQ(module(program, Stage::Fragment).location("tessref_FragData"), 0u);
}

TEST(GlslCompile, VersionLinesBecome450Core) {
  const char* no_version = "void main() { gl_Position = vec4(0.0); }\n";
  const char* compatibility =
      "#version 150 compatibility\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n";
  const CompiledProgram program =
      compile_program({{Stage::Vertex, "a.vert", 7, no_version},
                       {Stage::Fragment, "a.frag", 12, compatibility}});
  EXPECT_EQ(stage(program, Stage::Vertex).rewrites,
            std::vector<std::string>{
                "a.vert:7: no #version (GLSL 1.10): compiled as #version 450 core"});
  EXPECT_EQ(stage(program, Stage::Fragment).rewrites,
            std::vector<std::string>{
                "a.frag:12: #version 150 compatibility compiled as #version 450 core"});
  const char* v400 = "#version 400\nvoid main() { gl_Position = vec4(0.0); }\n";
  EXPECT_THAT(stage(compile_program({{Stage::Vertex, "b.vert", 1, v400}}), Stage::Vertex).rewrites,
              Contains("b.vert:1: #version 400 compiled as #version 450 core"));
}

TEST(GlslCompile, CoreExtensionLinesAreRemoved) {
  const char* control = R"(#version 150
#extension GL_ARB_tessellation_shader: require
#extension GL_ARB_arrays_of_arrays : require
layout(vertices = 4) out;
void main() {
  float levels[2][2] = float[2][2](float[2](2.0, 3.0), float[2](4.0, 5.0));
  gl_TessLevelOuter = float[4](levels[0][0], levels[0][1], levels[1][0], levels[1][1]);
  gl_TessLevelInner = float[2](1.0, 1.0);
}
)";
  const char* evaluation = R"(#version 150
#extension GL_ARB_tessellation_shader : require
layout(quads) in;
void main() { gl_Position = vec4(gl_TessCoord, 1.0); }
)";
  const CompiledProgram program =
      compile_program({{Stage::Vertex, "e.vert", 1, kPassThroughVertex},
                       {Stage::TessControl, "e.tesc", 1, control},
                       {Stage::TessEval, "e.tese", 1, evaluation}});
  EXPECT_THAT(stage(program, Stage::TessControl).rewrites,
              AllOf(Contains("e.tesc:2: removed '#extension GL_ARB_tessellation_shader : require' "
                             "(core in GLSL 4.50)"),
                    Contains("e.tesc:3: removed '#extension GL_ARB_arrays_of_arrays : require' "
                             "(core in GLSL 4.50)")));
  EXPECT_THAT(stage(program, Stage::TessEval).rewrites,
              Contains(HasSubstr("e.tese:2: removed '#extension GL_ARB_tessellation_shader")));
}

TEST(GlslCompile, AttributeAndVaryingBecomeInAndOut) {
  const char* vertex = R"(#version 120
attribute vec4 position;
attribute vec4 tint;
varying vec4 v_tint;
void main() { gl_Position = position; v_tint = tint; }
)";
  const char* fragment = R"(#version 120
varying vec4 v_tint;
uniform sampler2D tex;
void main() { gl_FragColor = v_tint * texture2D(tex, vec2(0.5)); }
)";
  const CompiledProgram program = compile_program(
      {{Stage::Vertex, "v.vert", 1, vertex}, {Stage::Fragment, "v.frag", 1, fragment}});
  EXPECT_THAT(stage(program, Stage::Vertex).rewrites,
              AllOf(Contains("v.vert:2: 'attribute' read as 'in' (2 times)"),
                    Contains("v.vert:4: 'varying' read as 'out'")));
  EXPECT_THAT(stage(program, Stage::Fragment).rewrites,
              AllOf(Contains("v.frag:2: 'varying' read as 'in'"),
                    Contains("v.frag:4: 'texture2D' read as 'texture'")));
  EXPECT_EQ(module(program, Stage::Vertex).location("v_tint"),
            module(program, Stage::Fragment).location("v_tint"));
}

// ---------------------------------------------------------------------------------------------
// Errors (a link error points at the input's first use: glslang keeps no declaration lines)

TEST(GlslCompile, SyntaxErrorNamesTheUsersLine) {
  // Line 3 of the text, which starts at line 20 of the file; the gl_FragColor rewrite inserts a
  // declaration above, which must not shift the numbering.
  const char* fragment = "#version 150\nvoid main() {\n  gl_FragColor = vec4(undeclared);\n}\n";
  EXPECT_EQ(error_of({{Stage::Vertex, "s.shader_test", 5, kPassThroughVertex},
                      {Stage::Fragment, "s.shader_test", 20, fragment}}),
            "s.shader_test:22: error: 'undeclared' : undeclared identifier");
}

// Issue 24, defect 5: glslang's terse messages say what they mean for a GL program.
TEST(GlslCompile, TerseCompilerMessagesAreExplained) {
  const char* recursive =
      "#version 450\nout vec4 c;\nfloat g(float x);\nfloat f(float x) { return g(x); }\n"
      "float g(float x) { return f(x); }\nvoid main() { c = vec4(f(1.0)); }\n";
  EXPECT_THAT(error_of({{Stage::Vertex, "r.vert", 1, kPassThroughVertex}, {Stage::Fragment, "r.frag", 1, recursive}}),
              AllOf(HasSubstr("r.frag: error: link error: fragment shader: Recursion detected: "),
                    HasSubstr("() calls "), HasSubstr("(), and the calls lead back to it; GLSL forbids recursion")));
  const char* subgroup =
      "#version 450\n#extension GL_KHR_shader_subgroup_ballot : require\nout vec4 c;\n"
      "void main() { c = vec4(subgroupBallot(true)); }\n";
  EXPECT_THAT(error_of({{Stage::Vertex, "s.vert", 1, kPassThroughVertex}, {Stage::Fragment, "s.frag", 1, subgroup}}),
              HasSubstr("s.frag:4: error: 'subgroup op' : requires SPIR-V 1.3: tessref compiles GLSL for OpenGL 4.5 "
                        "(SPIR-V 1.0), which has no subgroup operations"));
  const char* tokens = "#version 450\n#ifdef A\n#endif A\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n";
  EXPECT_THAT(error_of({{Stage::Vertex, "t.vert", 1, kPassThroughVertex}, {Stage::Fragment, "t.frag", 1, tokens}}),
              HasSubstr("t.frag:3: error: '#endif' : unexpected tokens following directive (the directive has more on "
                        "its line than GLSL allows: only a comment may follow it)"));
}

TEST(GlslCompile, ErrorsOfSeveralShadersAreAllReported) {
  const char* bad_vertex = "#version 450\nvoid main() { gl_Position = 1 +; }\n";
  const char* bad_fragment = "#version 450\nvoid main() {\n  nothing();\n}\n";
  const std::string error = error_of(
      {{Stage::Vertex, "a.vert", 1, bad_vertex}, {Stage::Fragment, "a.frag", 1, bad_fragment}});
  EXPECT_THAT(error, AllOf(HasSubstr("a.vert:2: error: "), HasSubstr("a.frag:3: error: ")));
}

TEST(GlslCompile, InputWithoutOutputIsALinkError) {
  const char* evaluation = R"(#version 450
layout(triangles) in;
in vec4 missing[];
void main() { gl_Position = missing[0]; }
)";
  EXPECT_EQ(error_of({{Stage::Vertex, "l.vert", 1, kVertex},
                      {Stage::TessControl, "l.tesc", 1, kControl},
                      {Stage::TessEval, "l.tese", 1, evaluation}}),
            "l.tese:4: error: link error: tessellation evaluation shader input 'missing' has no "
            "matching output in the tessellation control shader");
}

TEST(GlslCompile, TypeMismatchIsALinkError) {
  const char* fragment = R"(#version 450
in vec3 color;
layout(location = 0) out vec4 out_color;
void main() { out_color = vec4(color, 1.0); }
)";
  EXPECT_EQ(error_of({{Stage::Vertex, "m.vert", 1, kVertex},
                      {Stage::Fragment, "m.frag", 1, fragment}}),
            "m.frag:4: error: link error: fragment shader input 'color' is vec3 but the vertex "
            "shader output 'color' (m.vert:7) is vec4");
}

// GL matches by location when both sides have one (names aside), by name when neither has; a
// location on one side only is no match, as Mesa links it (the GPU would read undefined values).
TEST(GlslCompile, LocationOnOneSideOnlyMatchesNothing) {
  const char* vertex = "#version 450\nlayout(location = 0) in vec4 p;\nout vec4 color;\n"
                       "void main() { color = p; gl_Position = p; }\n";
  const char* located_fragment = "#version 450\nlayout(location = 2) in vec4 color;\nout vec4 c;\nvoid main() {\n  c = color;\n}\n";
  EXPECT_EQ(error_of({{Stage::Vertex, "a.vert", 1, vertex}, {Stage::Fragment, "a.frag", 1, located_fragment}}),
            "a.frag:5: error: link error: fragment shader input 'color' has location 2 but the vertex shader "
            "output (a.vert:4) of that name has none: GL matches by name only when neither side has a "
            "location, so on a driver the input would have no matching output (give both the same location, "
            "or neither)");
  const char* located_vertex = "#version 450\nlayout(location = 0) in vec4 p;\nlayout(location = 3) out vec4 color;\n"
                               "void main() { color = p; gl_Position = p; }\n";
  const char* fragment = "#version 450\nin vec4 color;\nout vec4 c;\nvoid main() {\n  c = color;\n}\n";
  EXPECT_THAT(error_of({{Stage::Vertex, "b.vert", 1, located_vertex}, {Stage::Fragment, "b.frag", 1, fragment}}),
              HasSubstr("input 'color' has no location but the vertex shader output (b.vert:4) of that name has location 3"));
  // Both located: the names need not agree.
  const char* other_name = "#version 450\nlayout(location = 3) in vec4 tint;\nout vec4 c;\nvoid main() {\n  c = tint;\n}\n";
  EXPECT_EQ(error_of({{Stage::Vertex, "c.vert", 1, located_vertex}, {Stage::Fragment, "c.frag", 1, other_name}}), "");
}

TEST(GlslCompile, UnusedInputNeedsNoOutput) {
  const char* fragment = R"(#version 450
in vec4 never_read;
layout(location = 0) out vec4 out_color;
void main() { out_color = vec4(1.0); }
)";
  EXPECT_EQ(error_of({{Stage::Vertex, "u.vert", 1, kVertex},
                      {Stage::Fragment, "u.frag", 1, fragment}}),
            "");
}

TEST(GlslCompile, TessellationWithoutVertexShaderIsALinkError) {
  EXPECT_EQ(error_of({{Stage::TessControl, "n.tesc", 3, kControl}}),
            "n.tesc:3: error: link error: a tessellation control shader needs a vertex shader in "
            "the program");
}

TEST(GlslCompile, GeometryShadersCompileAndNeedAVertexShader) {
  const char* geometry = R"(#version 150
layout(triangles, invocations = 2) in;
layout(triangle_strip, max_vertices = 3) out;
void main() { EmitVertex(); }
)";
  const CompiledProgram program = compile_program({{Stage::Vertex, "g.shader_test", 4, kPassThroughVertex},
                                                   {Stage::Geometry, "g.shader_test", 9, geometry}});
  ASSERT_EQ(program.stages.size(), 2u);
  EXPECT_EQ(program.stages[1].stage, Stage::Geometry);
  const auto m = ::tessref::shader::read_module(program.stages[1].spirv, {});
  EXPECT_EQ(m.modes.input_vertices, 3);
  EXPECT_EQ(m.modes.output_vertices, 3);
  EXPECT_EQ(m.modes.invocations, 2);
  EXPECT_EQ(m.modes.output_primitive, std::uint32_t(spv::ExecutionModeOutputTriangleStrip));
  // GL 4.5 section 7.3: a program with a geometry shader needs a vertex shader.
  EXPECT_EQ(error_of({{Stage::Geometry, "g.shader_test", 9, geometry}}),
            "g.shader_test:9: error: link error: a geometry shader needs a vertex shader in the program");
}

// GLSL 4.50 section 4.4.2.1: more output patch vertices than GL_MAX_PATCH_VERTICES is a compile
// error at the declaration (glslang does not check it).
TEST(GlslCompile, OutputPatchPastGlMaxPatchVerticesIsRefused) {
  auto control = [](int n) {
    return "#version 450\n// an output patch\n\nlayout(vertices = " + std::to_string(n) +
           ") out;\nvoid main() {\n  gl_TessLevelOuter[0] = 1.0;\n}\n";
  };
  const char* evaluation = "#version 450\nlayout(triangles) in;\nvoid main() { gl_Position = vec4(0.0); }\n";
  EXPECT_EQ(error_of({{Stage::Vertex, "p.shader_test", 2, kPassThroughVertex},
                      {Stage::TessControl, "p.shader_test", 10, control(33)},
                      {Stage::TessEval, "p.shader_test", 20, evaluation}}),
            "p.shader_test:13: error: layout(vertices = 33) is more than GL_MAX_PATCH_VERTICES (32): an output "
            "patch has 1 to 32 vertices");
  EXPECT_EQ(error_of({{Stage::Vertex, "p.shader_test", 2, kPassThroughVertex},
                      {Stage::TessControl, "p.shader_test", 10, control(32)},
                      {Stage::TessEval, "p.shader_test", 20, evaluation}}),
            "");
}

TEST(GlslCompile, FixedFunctionStateIsRefused) {
  const char* vertex = R"(#version 150 compatibility
in vec4 piglit_vertex;
void main() {
  gl_Position = gl_ModelViewProjectionMatrix * piglit_vertex;
}
)";
  EXPECT_EQ(error_of({{Stage::Vertex, "f.shader_test", 10, vertex}}),
            "f.shader_test:13: error: 'gl_ModelViewProjectionMatrix' is compatibility-profile "
            "fixed-function state, which tessref does not support; pass the matrix as a uniform "
            "instead");
  const char* clip = "#version 150 compatibility\nvoid main() { gl_ClipVertex = vec4(0.0); }\n";
  EXPECT_THAT(error_of({{Stage::Vertex, "c.vert", 1, clip}}),
              HasSubstr("c.vert:2: error: 'gl_ClipVertex' is compatibility-profile"));
}

// In a compatibility-profile context (piglit's shader_runner), the state the runner feeds becomes
// declared variables, each noted; gl_ClipVertex a location-31 output (gl_in[i].gl_ClipVertex an
// input array there); what it does not feed stays refused.
TEST(GlslCompile, CompatibilityStateTheCallerFeedsIsDeclared) {
  const char* vertex = "#version 130\nvoid main() {\n  gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;\n"
                       "  gl_FrontColor = vec4(1.0);\n}\n";
  const char* fragment = "#version 130\nvoid main() { gl_FragColor = gl_Color; }\n";
  shader::ShaderSource vs{Stage::Vertex, "c.shader_test", 10, vertex, true};
  const shader::RewrittenSource r = shader::rewrite_glsl(vs);
  EXPECT_THAT(r.text, HasSubstr("uniform mat4 tessref_ModelViewProjectionMatrix;\nin vec4 tessref_Vertex;\n"
                                "out vec4 tessref_Color;\n#line 10\n"));
  EXPECT_THAT(r.text, HasSubstr("gl_Position = tessref_ModelViewProjectionMatrix * tessref_Vertex;"));
  EXPECT_THAT(r.notes, Contains("c.shader_test:12: gl_Vertex read as 'in vec4 tessref_Vertex;' (compatibility profile)"));
  const shader::CompiledProgram p =
      shader::compile_program({vs, {Stage::Fragment, "c.shader_test", 20, fragment, true}});
  EXPECT_EQ(p.stages.size(), 2u);
  // The same text outside a compatibility context is refused, as is gl_ClipVertex within one.
  EXPECT_THAT(error_of({{Stage::Vertex, "c.shader_test", 10, vertex}}), HasSubstr("'gl_ModelViewProjectionMatrix' is"));
  shader::ShaderSource tes{Stage::TessEval, "e.tese", 1,
                          "#version 150\nlayout(triangles) in;\nvoid main() {\n"
                          "  gl_ClipVertex = gl_in[1].gl_ClipVertex * gl_TessCoord.y;\n}\n",
                          true};
  const shader::RewrittenSource e = shader::rewrite_glsl(tes);
  EXPECT_THAT(e.text, HasSubstr("layout(location = 31) in vec4 tessref_ClipVertexIn[];\n"
                                "layout(location = 31) out vec4 tessref_ClipVertex;\n"));
  EXPECT_THAT(e.text, HasSubstr("tessref_ClipVertex = tessref_ClipVertexIn[1] * gl_TessCoord.y;"));
  shader::ShaderSource back{Stage::Vertex, "v.vert", 1,
                            "#version 130\nvoid main() { gl_BackSecondaryColor = vec4(0.0); }\n", true};
  EXPECT_THROW(shader::rewrite_glsl(back), shader::CompileError);
}

// GL_CLAMP_VERTEX_COLOR: the last stage's colours are clamped per vertex when main() returns
// (the stage before keeps its own), or at each EmitVertex() of a geometry shader.
TEST(GlslCompile, VertexColoursAreClampedWhereTheLastStageWritesThem) {
  shader::ShaderSource vs{Stage::Vertex, "v.vert", 1,
                          "#version 150\nvoid main() {\n  gl_FrontColor = vec4(-2.0, 0.5, 3.0, 1.0);\n"
                          "  gl_FrontSecondaryColor = vec4(2.0);\n  if (gl_VertexID > 0) return;\n}\n",
                          true, true};
  const shader::RewrittenSource r = shader::rewrite_glsl(vs);
  EXPECT_THAT(r.text, HasSubstr("void tessref_main() {"));
  EXPECT_THAT(r.text, HasSubstr("\nvoid main() { tessref_main(); tessref_Color = clamp(tessref_Color, 0.0, 1.0); "
                                "tessref_SecondaryColor = clamp(tessref_SecondaryColor, 0.0, 1.0); }\n"));
  EXPECT_THAT(r.notes, Contains("v.vert:2: vertex colours clamped to [0, 1] when main() returns (compatibility "
                                "profile: GL_CLAMP_VERTEX_COLOR)"));
  vs.clamp_vertex_color = false;
  EXPECT_THAT(shader::rewrite_glsl(vs).text, Not(HasSubstr("clamp(")));
  shader::ShaderSource gs{Stage::Geometry, "g.geom", 1,
                          "#version 150\nlayout(points) in;\nlayout(points, max_vertices = 1) out;\n"
                          "void main() { gl_FrontColor = vec4(2.0); EmitVertex(); }\n",
                          true, true};
  const shader::RewrittenSource g = shader::rewrite_glsl(gs);
  EXPECT_THAT(g.text, HasSubstr("void tessref_EmitVertex() { tessref_Color = clamp(tessref_Color, 0.0, 1.0); EmitVertex(); }"));
  EXPECT_THAT(g.text, HasSubstr("void main() { tessref_Color = vec4(2.0); tessref_EmitVertex(); }"));
  const shader::CompiledProgram p = shader::compile_program(
      {vs, gs, {Stage::Fragment, "f.frag", 1, "#version 150\nvoid main() { gl_FragColor = gl_Color; }\n", true}});
  EXPECT_EQ(p.stages.size(), 3u);
}

// OpenGL 4.5, 7.4: a separable program's shaders of GLSL 1.50 and later redeclare the
// gl_PerVertex blocks they use; 1.40 ones need not, and separate programs are not checked
// against each other (Mesa's rules, which piglit's arb_separate_shader_objects tests follow).
TEST(GlslCompile, SeparableProgramsRedeclareTheBuiltInBlocksTheyUse) {
  const char* vs150 = "#version 150\nvoid main() {\n  gl_Position = vec4(0.0);\n}\n";
  const char* fs = "#version 150\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n";
  const std::vector<shader::ShaderSource> implicit{{Stage::Vertex, "v.vert", 1, vs150}, {Stage::Fragment, "f.frag", 1, fs}};
  EXPECT_NO_THROW(shader::compile_program(implicit));
  EXPECT_NO_THROW(shader::compile_program(implicit, shader::Linking::SeparatePrograms));
  try {
    shader::compile_program(implicit, shader::Linking::SeparableProgram);
    ADD_FAILURE() << "linked";
  } catch (const shader::CompileError& e) {
    EXPECT_THAT(e.what(), HasSubstr("v.vert:3: error: link error: the vertex shader uses the built-in output block "
                                    "gl_PerVertex without redeclaring it ('out gl_PerVertex { ... }')"));
  }
  const char* redeclared = "#version 150\nout gl_PerVertex { vec4 gl_Position; };\nvoid main() { gl_Position = vec4(0.0); }\n";
  EXPECT_NO_THROW(shader::compile_program({{Stage::Vertex, "v.vert", 1, redeclared}, {Stage::Fragment, "f.frag", 1, fs}},
                                          shader::Linking::SeparableProgram));
  const char* vs140 = "#version 140\nvoid main() { gl_Position = vec4(0.0); }\n";
  const char* fs140 = "#version 140\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n";
  EXPECT_NO_THROW(shader::compile_program({{Stage::Vertex, "v.vert", 1, vs140}, {Stage::Fragment, "f.frag", 1, fs140}},
                                          shader::Linking::SeparableProgram));
  // An input that the stage before does not write is a link error in one program, not across two.
  const char* reads = "#version 150\nin vec4 missing;\nout vec4 c;\nvoid main() { c = missing; }\n";
  const std::vector<shader::ShaderSource> unmatched{{Stage::Vertex, "v.vert", 1, vs150}, {Stage::Fragment, "f.frag", 1, reads}};
  EXPECT_THROW(shader::compile_program(unmatched), shader::CompileError);
  EXPECT_NO_THROW(shader::compile_program(unmatched, shader::Linking::SeparatePrograms));
}

TEST(GlslCompile, OpenGlEsIsRefused) {
  const char* es = "#version 310 es\nvoid main() {}\n";
  EXPECT_THAT(error_of({{Stage::Vertex, "es.vert", 1, es}}),
              HasSubstr("es.vert:1: error: OpenGL ES shaders are not supported"));
}

TEST(GlslCompile, CompilationUnitsOfOneStageAreLinked) {
  const char* helper = "#version 450\nvec4 shade(vec4 c) { return c * 2.0; }\n";
  const char* main_unit = R"(#version 450
in vec4 color;
layout(location = 0) out vec4 out_color;
vec4 shade(vec4 c);
void main() { out_color = shade(color); }
)";
  const CompiledProgram program =
      compile_program({{Stage::Vertex, "c.vert", 1, kVertex},
                       {Stage::Fragment, "main.frag", 1, main_unit},
                       {Stage::Fragment, "helper.frag", 1, helper}});
  const Module fs = module(program, Stage::Fragment);
  EXPECT_FALSE(fs.has(spv::Op::OpFunctionCall));
  EXPECT_THAT(fs.lines(), Contains("helper.frag:2"));
}

// ---------------------------------------------------------------------------------------------
// The project's own GLSL twins

std::string read_twin(const std::string& path) {
  std::ifstream file(std::string(TESSREF_SOURCE_DIR) + "/" + path);
  std::stringstream text;
  text << file.rdbuf();
  if (!file) throw std::runtime_error("cannot read " + path);
  return text.str();
}

ShaderSource twin(Stage stage, const std::string& path) {
  return {stage, path, 1, read_twin(path)};
}

void expect_twins_link(const std::string& scheme) {
  SCOPED_TRACE(scheme);
  const CompiledProgram program =
      compile_program({twin(Stage::Vertex, "stages/programs/transform.vert"),
                       twin(Stage::TessControl, "stages/schemes/" + scheme + ".tesc"),
                       twin(Stage::TessEval, "stages/schemes/" + scheme + ".tese"),
                       twin(Stage::Fragment, "stages/programs/phong.frag")});
  ASSERT_EQ(program.stages.size(), 4u);
  for (const CompiledStage& s : program.stages) {
    EXPECT_TRUE(s.rewrites.empty()) << stage_name(s.stage);
    EXPECT_FALSE(Module(s.spirv).has(spv::Op::OpFunctionCall)) << stage_name(s.stage);
  }
  const Module tcs = module(program, Stage::TessControl), tes = module(program, Stage::TessEval);
  ASSERT_TRUE(tcs.location("tcs_out"));
  EXPECT_EQ(tcs.location("tcs_out"), tes.location("tes_in")) << "block StageVertex";
  EXPECT_EQ(module(program, Stage::Vertex).location("v_world_normal"),
            tcs.location("v_world_normal"));
  EXPECT_EQ(tes.location("v_world_normal"),
            module(program, Stage::Fragment).location("v_world_normal"));
}

TEST(GlslCompile, PnTrianglesTwinsLink) {
  expect_twins_link("pn_triangles");
  const CompiledProgram program =
      compile_program({twin(Stage::Vertex, "stages/programs/transform.vert"),
                       twin(Stage::TessControl, "stages/schemes/pn_triangles.tesc"),
                       twin(Stage::TessEval, "stages/schemes/pn_triangles.tese"),
                       twin(Stage::Fragment, "stages/programs/phong.frag")});
  // A patch array between TCS and TES (glslang 12's own cross-stage check refuses it).
  EXPECT_EQ(module(program, Stage::TessControl).location("pn_patch"),
            module(program, Stage::TessEval).location("pn_patch"));
  // The same uniform has the same location in every stage.
  EXPECT_EQ(module(program, Stage::TessControl).location("u_view_proj"),
            module(program, Stage::TessEval).location("u_view_proj"));
}

TEST(GlslCompile, FlatTwinsLink) { expect_twins_link("flat"); }

}  // namespace
}  // namespace tessref::shader
