// `tessref render --check` (pipeline/check.h): a planted NaN in a user's evaluation shader is found
// with its patch, coordinate and source line; clean scenes render the same bytes with --check;
// a NaN tessellation level is a warning, not an offence.
#include <filesystem>
#include <fstream>
#include <iterator>

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

}  // namespace
}  // namespace tessref
