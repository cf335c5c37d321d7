// `tessref render --check` (check/check.h): a planted NaN in a user's vertex, control,
// evaluation or fragment shader is found with its stage, vertex/patch/pixel, invocation and source
// line; clean scenes render the same bytes with --check; a NaN tessellation level is a warning, not
// an offence; `--check-range` (check/check_range.h) reports values outside a range the same way.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <utility>

#include <gtest/gtest.h>

#include "tests/pipeline/test_util.h"

namespace tessref {
namespace {

const std::string kDisplacement = std::string(TESSREF_SOURCE_DIR) + "/scenes/displacement.json";

// The flat twin's evaluation shader, cut down, with a NaN planted on line 13 for patch 37 only,
// in one region of its domain. sqrt of a computed negative number: glslang cannot fold it away.
const char* kPlantedTes = R"(#version 450
layout(triangles, fractional_odd_spacing, ccw) in;
in StageVertex { vec4 attr[8]; } tes_in[];
layout(location = 0) out vec3 v_world_position;
layout(location = 1) out vec3 v_world_normal;
uniform mat4 u_view_proj;
void main() {
  vec3 b = gl_TessCoord;
  vec3 p = tes_in[0].attr[0].xyz * b.x + tes_in[1].attr[0].xyz * b.y + tes_in[2].attr[0].xyz * b.z;
  vec3 n = tes_in[0].attr[1].xyz * b.x + tes_in[1].attr[1].xyz * b.y + tes_in[2].attr[1].xyz * b.z;
  float bump = 0.0;
  if (gl_PrimitiveID == 37 && b.x > 0.5)
    bump = sqrt(b.y - 2.0);
  v_world_position = p + bump;
  v_world_normal = normalize(n);
  gl_Position = u_view_proj * vec4(p + bump, 1.0);
}
)";

std::string planted_args(const test::TempDir& dir, int threads = 2) {
  const auto tes = dir.write("planted.tese", kPlantedTes);
  return kDisplacement + " --set shaders.tess_evaluation=" + tes.string() +
         " --set 'shaders.uniforms={\"u_amplitude\": null, \"u_frequency\": null}' --threads " +
         std::to_string(threads);
}

std::string read_all(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

TEST(RenderCheck, PlantedNanIsFoundWithItsSourceLine) {
  test::TempDir dir;
  const auto out = dir.path() / "x.png";
  const test::CliRun r = test::run_cli("render " + planted_args(dir) + " --check -o " + out.string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("stage: tessellation evaluation shader"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("patch: 37 (gl_PrimitiveID)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("gl_TessCoord ("), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--patch 37 --coord "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("planted.tese:13: bump = sqrt(b.y - 2.0);"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("OpExtInst Sqrt, operands finite"), std::string::npos) << r.output;
  // Nothing written, no temporary left behind: only the shader is in the folder.
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);

  // The same on one thread: the first offence does not depend on the thread count.
  const test::CliRun one = test::run_cli("render " + planted_args(dir, 1) + " --check -o " + out.string());
  EXPECT_EQ(one.exit_code, 1);
  EXPECT_EQ(one.output, r.output);

  // The inspect command it prints runs.
  const std::size_t at = r.output.find("inspect: tessref ");
  ASSERT_NE(at, std::string::npos);
  const std::string inspect = r.output.substr(at + 17, r.output.find('\n', at) - at - 17);
  const test::CliRun shown = test::run_cli(inspect);
  EXPECT_EQ(shown.exit_code, 0) << inspect << "\n" << shown.output;
}

TEST(RenderCheck, WithoutCheckThePlantedSceneRenders) {
  test::TempDir dir;
  const auto out = dir.path() / "x.png";
  const test::CliRun r = test::run_cli("render " + planted_args(dir) + " -o " + out.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(out));
}

TEST(RenderCheck, CleanSceneGivesTheSameBytes) {
  test::TempDir dir;
  const auto plain = dir.path() / "plain.png", checked = dir.path() / "checked.png";
  ASSERT_EQ(test::run_cli("render -o " + plain.string()).exit_code, 0);
  const test::CliRun r = test::run_cli("render --check -o " + checked.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read_all(plain), read_all(checked));
  EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;
}

TEST(RenderCheck, NanLevelIsAWarning) {
  test::TempDir dir;
  const auto out = dir.path() / "x.png";
  const test::CliRun r = test::run_cli("render --check --set tessellation.outer=nan -o " + out.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("warning: --check: 256 patch(es) have a NaN tessellation level"), std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("stage:"), std::string::npos) << r.output;
}

// The other stages: the twins' interfaces, cut down, each with one planted non-finite value.
// log() of a computed negative number for gl_VertexID 17 only, on line 13.
const char* kPlantedVert = R"(#version 450
layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
uniform mat4 u_model;
uniform mat4 u_view_projection;
uniform mat3 u_normal_matrix;
layout(location = 0) out vec3 v_world_position;
layout(location = 1) out vec3 v_world_normal;
void main() {
  vec4 world = u_model * vec4(in_position, 1.0);
  float bend = 0.0;
  if (gl_VertexID == 17)
    bend = log(world.y - 100.0);
  gl_Position = u_view_projection * (world + bend);
  v_world_position = world.xyz;
  v_world_normal = u_normal_matrix * in_normal;
}
)";

// inversesqrt(0) = +inf on line 20, after the barrier (phase 1), by invocation 1 of patch 5 only.
const char* kPlantedTesc = R"(#version 450
layout(vertices = 3) out;
layout(location = 0) in vec3 v_world_position[];
layout(location = 1) in vec3 v_world_normal[];
out StageVertex { vec4 attr[8]; } tcs_out[];
uniform vec4 u_outer;
uniform vec2 u_inner;
void main() {
  tcs_out[gl_InvocationID].attr[0] = vec4(v_world_position[gl_InvocationID], 1.0);
  tcs_out[gl_InvocationID].attr[1] = vec4(v_world_normal[gl_InvocationID], 0.0);
  for (int s = 2; s < 8; ++s) tcs_out[gl_InvocationID].attr[s] = vec4(0.0);
  if (gl_InvocationID == 0) {
    gl_TessLevelOuter = float[4](u_outer.x, u_outer.y, u_outer.z, u_outer.w);
    gl_TessLevelInner = float[2](u_inner.x, u_inner.y);
  }
  barrier();
  vec3 next = tcs_out[(gl_InvocationID + 1) % 3].attr[0].xyz;
  float s = 1.0;
  if (gl_PrimitiveID == 5 && gl_InvocationID == 1)
    s = inversesqrt(next.x - next.x);
  tcs_out[gl_InvocationID].attr[1] *= s;
}
)";

// acos(> 1) on line 10 in one corner of the window (gl_FragCoord x > 500, y < 400).
const char* kPlantedFrag = R"(#version 450
layout(location = 0) in vec3 v_world_position;
layout(location = 1) in vec3 v_world_normal;
uniform vec3 u_color;
layout(location = 0) out vec4 out_color;
void main() {
  vec3 n = normalize(v_world_normal);
  vec3 c = u_color * max(n.z, 0.0);
  if (gl_FragCoord.x > 500.0 && gl_FragCoord.y < 400.0)
    c.y = acos(c.y + 3.0);
  out_color = vec4(c, 1.0);
}
)";

// Renders the displacement scene with one stage replaced, --check, on `threads` threads.
test::CliRun render_planted(const test::TempDir& dir, const std::string& stage, const std::string& file,
                            const char* text, int threads) {
  const auto path = dir.write(file, text);
  return test::run_cli("render " + kDisplacement + " --set shaders." + stage + "=" + path.string() +
                       " --check --threads " + std::to_string(threads) + " -o " + (dir.path() / "x.png").string());
}

// The report's line starting with `key` (without the key), or "".
std::string line_of(const std::string& report, const std::string& key) {
  const std::size_t at = report.find("\n" + key);
  if (at == std::string::npos) return "";
  const std::size_t from = at + 1 + key.size();
  return report.substr(from, report.find('\n', from) - from);
}

TEST(RenderCheck, PlantedNanInTheVertexShader) {
  test::TempDir dir;
  const test::CliRun r = render_planted(dir, "vertex", "planted.vert", kPlantedVert, 2);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_EQ(line_of(r.output, "stage: "), "vertex shader") << r.output;
  // Vertex 17 is first used by patch 16 of the torus's index buffer.
  EXPECT_EQ(line_of(r.output, "vertex: "), "17 (gl_VertexID; first used by patch 16)") << r.output;
  EXPECT_EQ(line_of(r.output, "output: "), "gl_Position.x = nan") << r.output;
  EXPECT_NE(line_of(r.output, "first NaN: ").find("planted.vert:13: bend = log(world.y - 100.0);  (OpExtInst Log, operands finite)"),
            std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "x.png"));
  EXPECT_EQ(render_planted(dir, "vertex", "planted.vert", kPlantedVert, 1).output, r.output);
}

TEST(RenderCheck, PlantedInfInTheControlShaderNamesInvocationAndPhase) {
  test::TempDir dir;
  const test::CliRun r = render_planted(dir, "tess_control", "planted.tesc", kPlantedTesc, 2);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_EQ(line_of(r.output, "stage: "), "tessellation control shader") << r.output;
  EXPECT_EQ(line_of(r.output, "patch: "), "5 (gl_PrimitiveID)") << r.output;
  EXPECT_EQ(line_of(r.output, "invocation: "), "gl_InvocationID 1, phase 1 (after 1 barrier())") << r.output;
  // The normal times +inf: gl_out[1]'s attr[1] (I/O location 1), x first.
  EXPECT_EQ(line_of(r.output, "output: ").rfind("gl_out[1] location 1.x = ", 0), 0u) << r.output;
  EXPECT_NE(line_of(r.output, "first Inf: ").find("planted.tesc:20: s = inversesqrt(next.x - next.x);  (OpExtInst InverseSqrt, operands finite)"),
            std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--patch 5\n"), std::string::npos) << r.output;
  EXPECT_EQ(render_planted(dir, "tess_control", "planted.tesc", kPlantedTesc, 1).output, r.output);
}

TEST(RenderCheck, PlantedNanInTheFragmentShaderNamesThePixel) {
  test::TempDir dir;
  const test::CliRun r = render_planted(dir, "fragment", "planted.frag", kPlantedFrag, 2);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_EQ(line_of(r.output, "stage: "), "fragment shader") << r.output;
  // The pixel as image files count it (Y from the top) and gl_FragCoord (from the bottom): the
  // planted region is x > 500, window y < 400, i.e. top-down Y > 1023 - 400.
  int x = -1, y = -1, wx = -1, wy = -1;
  ASSERT_EQ(std::sscanf(line_of(r.output, "pixel: ").c_str(), "%d,%d (X from the left, Y down from the top row; gl_FragCoord.xy (%d.5, %d.5)",
                        &x, &y, &wx, &wy), 4) << r.output;
  EXPECT_EQ(wx, x);
  EXPECT_EQ(wy, 1023 - y);
  EXPECT_GT(x, 500);
  EXPECT_LT(wy, 400);
  EXPECT_EQ(line_of(r.output, "output: "), "color.y = nan") << r.output;
  EXPECT_NE(r.output.find("--pixel " + std::to_string(x) + "," + std::to_string(y)), std::string::npos) << r.output;
  EXPECT_NE(line_of(r.output, "first NaN: ").find("planted.frag:10: c.y = acos(c.y + 3.0);  (OpExtInst Acos, operands finite)"),
            std::string::npos) << r.output;
  EXPECT_EQ(render_planted(dir, "fragment", "planted.frag", kPlantedFrag, 1).output, r.output);
}

TEST(RenderCheckRange, OutOfRangeIsReportedLikeANan) {
  test::TempDir dir;
  const auto out = dir.path() / "x.png";
  // The displacement scene's constant levels are 24: a range that excludes them.
  const test::CliRun levels = test::run_cli("render " + kDisplacement + " --check-range levels=1,20 -o " + out.string());
  EXPECT_EQ(levels.exit_code, 1) << levels.output;
  EXPECT_NE(levels.output.find("tessref render --check: value out of range, nothing written\n"
                               "stage: tessellation control shader\npatch: 0 (gl_PrimitiveID)\n"
                               "output: gl_TessLevelOuter[0] = 24 outside [1, 20] (--check-range levels=1,20)\n"
                               "inspect: tessref inspect " + kDisplacement + " --patch 0"),
            std::string::npos) << levels.output;
  EXPECT_FALSE(std::filesystem::exists(out));

  // An evaluation output by its GLSL name: the displaced position's x, at the first point of
  // patch 0 outside [-0.5, 0.5].
  const test::CliRun pos = test::run_cli("render " + kDisplacement + " --check-range v_world_position.x=-0.5,0.5 -o " + out.string());
  EXPECT_EQ(pos.exit_code, 1) << pos.output;
  EXPECT_EQ(line_of(pos.output, "stage: "), "tessellation evaluation shader") << pos.output;
  float value = 0.0f;
  ASSERT_EQ(std::sscanf(line_of(pos.output, "output: ").c_str(), "v_world_position.x = %f outside [-0.5, 0.5]", &value), 1)
      << pos.output;
  EXPECT_GT(std::abs(value), 0.5f);
  EXPECT_NE(pos.output.find(" --coord "), std::string::npos) << pos.output;
}

TEST(RenderCheckRange, InRangeRendersTheSameBytes) {
  test::TempDir dir;
  const auto plain = dir.path() / "plain.png", checked = dir.path() / "checked.png";
  ASSERT_EQ(test::run_cli("render -o " + plain.string()).exit_code, 0);
  // The built-in programs' normals are unit length; gl_Position.w is the depth from the eye.
  const test::CliRun r = test::run_cli("render --check-range 'length(v_world_normal)=0.999,1.001' "
                                       "--check-range gl_Position.w=0.5,50 --check-range levels=12,12 -o " +
                                       checked.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read_all(plain), read_all(checked));
}

TEST(RenderCheckRange, BadRangesAreInputErrors) {
  test::TempDir dir;
  const auto out = dir.path() / "x.png";
  const std::pair<const char*, const char*> cases[] = {
      {"foo=1,2", "--check-range 'foo=1,2': unknown name 'foo'; this scene has gl_Position, v_world_position, v_world_normal"},
      {"levels=5,1", "--check-range 'levels=5,1': the lower bound is above the upper one (LO <= HI)"},
      {"levels=nan,1", "--check-range 'levels=nan,1': lower bound is NaN"},
      {"levels=1,x", "--check-range 'levels=1,x': upper bound 'x' is not a number"},
      {"levels=1", "--check-range 'levels=1': expected two bounds LO,HI after '='"},
      {"gl_Position.q=0,1", "'.q': a component is one of .x .y .z .w"},
      {"gl_TessLevelInner[2]=1,2", "gl_TessLevelInner has 2 elements"},
  };
  for (const auto& [spec, message] : cases) {
    const test::CliRun r = test::run_cli("render " + kDisplacement + " --check-range '" + spec + "' -o " + out.string());
    EXPECT_EQ(r.exit_code, 2) << spec << "\n" << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << spec << "\n" << r.output;
  }
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace tessref
