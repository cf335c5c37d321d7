// tessref inspect --trace (issue 10): the source-level trace is the draw's computation, not a
// second one: every value a traced invocation stores into its outputs equals, bit for bit, what
// inspect shows the draw handed to the next stage; the built-in programs are traced through their
// GLSL twins, which agree with them bit for bit; the TCS's barrier() is marked.
#include <bit>
#include <cstdint>
#include <map>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "inspect/inspect.h"
#include "inspect/inspect_pixel.h"
#include "test_util.h"

namespace tessref {
namespace {

using ::testing::HasSubstr;

// The traced invocation's stores, the last one to each target.
std::map<std::string, shader::TraceValue> stores(const InspectTrace& t) {
  std::map<std::string, shader::TraceValue> out;
  for (const shader::TraceLine& l : t.trace.lines)
    for (const shader::TraceStore& s : l.stores) out[s.target] = s.value;
  return out;
}

// The value's 32-bit words equal these floats' bits.
template <int N>
void expect_bits(const shader::TraceValue& v, const glm::vec<N, float>& f, const std::string& what) {
  ASSERT_EQ(v.scalars.size(), std::size_t(N)) << what;
  for (int i = 0; i < N; ++i) EXPECT_EQ(std::uint32_t(v.bits[std::size_t(i)]), std::bit_cast<std::uint32_t>(f[i])) << what << "[" << i << "]";
}

void expect_trace_matches(const InspectResult& r) {
  ASSERT_EQ(r.traces.size(), 3u + 3u + 1u);  // 3 corners, 3 control invocations, 1 point
  for (int k = 0; k < 3; ++k) {
    const InspectTrace& vs = r.traces[std::size_t(k)];
    EXPECT_EQ(vs.stage, shader::Stage::Vertex);
    EXPECT_EQ(vs.file, "transform.vert");
    const auto s = stores(vs);
    ASSERT_TRUE(s.count("gl_Position") && s.count("v_world_position"));
    const InspectCorner& c = r.corners[std::size_t(k)];
    if (r.traced_twins) {  // the C++ vertex shader: gl_Position apart, (world, 1) in slot 0
      expect_bits(s.at("gl_Position"), *c.gl_position, "vs gl_Position");
      expect_bits(s.at("v_world_position"), glm::vec3(c.vs_out.attr[0]), "vs position");
    } else {  // the executor's vertex stage: gl_Position in slot 0, the outputs after it
      expect_bits(s.at("gl_Position"), c.vs_out.attr[0], "vs gl_Position");
      expect_bits(s.at("v_world_position"), glm::vec3(c.vs_out.attr[1]), "vs position");
    }
  }
  for (int i = 0; i < 3; ++i) {
    const InspectTrace& tcs = r.traces[3 + std::size_t(i)];
    EXPECT_EQ(tcs.stage, shader::Stage::TessControl);
    EXPECT_EQ(tcs.invocation, "invocation " + std::to_string(i));
    const auto s = stores(tcs);
    // The executor's I/O slots put gl_Position first: the block's attr[a] is slot a + 1 there.
    const std::size_t first = r.traced_twins ? 0 : 1;
    for (int a = 0; a < 5; ++a) {
      const std::string target = "tcs_out[" + std::to_string(i) + "].attr[" + std::to_string(a) + "]";
      ASSERT_TRUE(s.count(target)) << target;
      expect_bits(s.at(target), r.tcs_out.vertices[std::size_t(i)].attr[first + std::size_t(a)], target);
    }
    int barriers = 0;
    for (const shader::TraceLine& l : tcs.trace.lines) barriers += l.barrier;
    EXPECT_EQ(barriers, 1) << "pn_triangles.tesc has one barrier()";
    EXPECT_EQ(s.count("gl_TessLevelOuter"), i == 0 ? 1u : 0u);  // invocation 0 writes the levels
  }
  const auto s = stores(r.traces.back());
  EXPECT_EQ(r.traces.back().stage, shader::Stage::TessEval);
  ASSERT_EQ(r.points.size(), 1u);
  expect_bits(s.at("gl_Position"), r.points[0].gl_position, "gl_Position");
  expect_bits(s.at("v_world_position"), r.points[0].position, "world position");
  expect_bits(s.at("v_world_normal"), r.points[0].normal, "world normal");
}

TEST(InspectTrace, GlslStoresAreTheValuesTheDrawHandsOn) {
  const test::LoadedScene l = test::load_default_scene({"shaders.program=twins"});
  for (std::size_t patch : {0u, 17u, 131u}) {
    InspectRequest q;
    q.patch = patch;
    q.vertex = 5;
    q.trace = kTraceAll;
    const InspectResult r = inspect_patch(l.scene, l.mesh, q);
    EXPECT_FALSE(r.traced_twins);
    EXPECT_EQ(r.tcs_phases, 2);  // pn_triangles.tesc's one barrier(), as the built-in program's 2 phases
    SCOPED_TRACE("patch " + std::to_string(patch));
    expect_trace_matches(r);
  }
}

TEST(InspectTrace, BuiltinProgramsAreTracedThroughTheirTwinsBitForBit) {
  for (const char* mode : {"quadratic", "analytic", "linear"}) {
    const test::LoadedScene l = test::load_default_scene({std::string("tessellation.normal_mode=") + mode});
    InspectRequest q;
    q.patch = 200;
    q.coord = glm::vec3(0.25f, 0.5f, 0.25f);
    q.trace = kTraceAll;
    const InspectResult r = inspect_patch(l.scene, l.mesh, q);
    EXPECT_TRUE(r.traced_twins);
    SCOPED_TRACE(mode);
    expect_trace_matches(r);  // the C++ program's values, reproduced by the twin's trace
  }
}

TEST(InspectTrace, StagesCanBeChosenAndAllPointsTraceNoEvaluation) {
  const test::LoadedScene l = test::load_default_scene({"shaders.program=twins"});
  InspectRequest q;
  q.patch = 3;
  q.trace = parse_trace_stages("control,evaluation");
  const InspectResult r = inspect_patch(l.scene, l.mesh, q);
  ASSERT_EQ(r.traces.size(), 3u);  // every point asked for: the evaluation shader is not traced
  for (const InspectTrace& t : r.traces) EXPECT_EQ(t.stage, shader::Stage::TessControl);
  EXPECT_THROW(parse_trace_stages("vertex,geometry"), InputError);
}

// --pixel on a GLSL program: the same fragments as the built-in programs draw (the twins agree
// bit for bit), their varyings, and a fragment shader trace whose colour store is the fragment's.
TEST(InspectTrace, PixelQueriesRunGlslProgramsAndTraceTheirFragmentShader) {
  const test::LoadedScene builtin = test::load_default_scene({});
  const test::LoadedScene twins = test::load_default_scene({"shaders.program=twins"});
  const Parallel parallel(2);
  for (const auto& [x, y] : {std::pair{512, 400}, std::pair{300, 620}}) {
    const PixelInspectResult b = inspect_pixel(builtin.scene, builtin.mesh, x, y, parallel, true);
    const PixelInspectResult g = inspect_pixel(twins.scene, twins.mesh, x, y, parallel, true);
    EXPECT_TRUE(b.traced_twins);
    EXPECT_FALSE(g.traced_twins);
    EXPECT_EQ(g.program, "glsl twins (executor)");
    ASSERT_FALSE(g.fragments.empty());
    ASSERT_EQ(g.fragments.size(), b.fragments.size());
    EXPECT_EQ(g.pixel_color, b.pixel_color);
    for (std::size_t i = 0; i < g.fragments.size(); ++i) {
      const PixelFragment& f = g.fragments[i];
      EXPECT_EQ(f.patch, b.fragments[i].patch);
      EXPECT_EQ(f.triangle, b.fragments[i].triangle);
      EXPECT_EQ(f.color, b.fragments[i].color);
      ASSERT_GE(f.inputs.size(), 6u);  // v_world_position, v_world_normal
      EXPECT_EQ(glm::vec3(f.inputs[0], f.inputs[1], f.inputs[2]), f.position);
      for (const PixelInspectResult* r : {&g, &b}) {
        const PixelFragment& traced = r->fragments[i];
        ASSERT_TRUE(traced.trace);
        EXPECT_EQ(traced.trace->stage, shader::Stage::Fragment);
        EXPECT_EQ(traced.trace->file, "phong.frag");
        expect_bits(stores(*traced.trace).at("out_color"), traced.color, "out_color");
      }
    }
  }
}

TEST(InspectTrace, CommandLinePrintsTheTraceAndItsJson) {
  const test::TempDir dir;
  const test::CliRun text = test::run_cli("inspect --patch 17 --coord 0.2,0.3,0.5 --trace --trace-stages evaluation");
  ASSERT_EQ(text.exit_code, 0) << text.output;
  EXPECT_THAT(text.output, HasSubstr("5. Source trace of the built-in programs' GLSL twins"));
  EXPECT_THAT(text.output, HasSubstr("tessellation evaluation shader pn_triangles.tese, gl_TessCoord (0.200000003, 0.300000012, 0.5)"));
  EXPECT_THAT(text.output, HasSubstr("93: v_world_position = p;"));
  const auto json_path = dir.path() / "t.json";
  const test::CliRun js = test::run_cli("inspect --patch 17 --vertex 2 --trace --json " + json_path.string());
  ASSERT_EQ(js.exit_code, 0) << js.output;
  const auto j = nlohmann::json::parse(test::read_file(json_path));
  const auto& inv = j.at("source_trace").at("invocations");
  ASSERT_EQ(inv.size(), 7u);
  const auto& last = inv.back().at("lines").back();
  EXPECT_THAT(last.at("source").get<std::string>(), HasSubstr("gl_Position = u_view_proj * vec4(p, 1.0);"));
  EXPECT_EQ(last.at("stores").at(0).at("target"), "gl_Position");
  EXPECT_EQ(last.at("stores").at(0).at("value").size(), 4u);
  // `mid = u_normal_mode == 2 ? h : safe_normalize(h);` keeps mid as a value, not in memory: the
  // line comes back after safe_normalize's lines with the value mid takes, which the next line
  // stores (issue 24: the trace showed the condition and never mid).
  const test::CliRun control = test::run_cli("inspect --patch 17 --vertex 5 --trace --trace-stages control");
  ASSERT_EQ(control.exit_code, 0) << control.output;
  EXPECT_THAT(control.output, HasSubstr("27: return v / sqrt(len2);"));
  EXPECT_THAT(control.output, ::testing::ContainsRegex(
      "103: mid = u_normal_mode == 2 \\? h : safe_normalize\\(h\\); +-> joined: \\(0.758645177, 0.557058692, 0.337850749\\)"));
  EXPECT_THAT(control.output, HasSubstr("-> tcs_out[0].attr[4] = (0.758645177, 0.557058692, 0.337850749, 0)"));
  const test::CliRun bad = test::run_cli("inspect --patch 1 --trace --trace-stages vertx");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_THAT(bad.output, HasSubstr("--trace-stages: unknown stage \"vertx\""));
}

}  // namespace
}  // namespace tessref
