// tessref inspect on scenes of draws: a draw's patch, found by --draw and --patch over the draw's
// calls and instances, shows the values the draw itself computes (every point's gl_TessCoord and
// dump fields bit for bit with render --dump-tess under the patch id inspect reports), with GL's
// numbering (gl_VertexID, gl_InstanceID, gl_PrimitiveID); bad requests exit 2 naming the option.
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tess_dump_text.h"
#include "test_util.h"

namespace tessref {
namespace {

using ::testing::HasSubstr;
using test::CliRun;
using test::run_cli;
using test::TempDir;

const std::string kDraws = std::string(TESSREF_SOURCE_DIR) + "/tests/data/draws/";

struct Case {
  std::string scene;
  int draw;
  std::vector<int> patches;  // counted within the draw
};

class InspectDraws : public ::testing::TestWithParam<Case> {};

TEST_P(InspectDraws, PointsAreTheDrawsBitForBit) {
  const Case& c = GetParam();
  TempDir dir;
  const std::string scene = kDraws + c.scene;
  const auto dump = test::render_dump(dir, " " + scene);
  for (int patch : c.patches) {
    const std::string args = scene + " --draw " + std::to_string(c.draw) + " --patch " + std::to_string(patch);
    const nlohmann::json all = test::inspect_json(dir, args);
    const int id = all["draw"]["patch_id"];
    ASSERT_TRUE(dump.count(id)) << args << ": patch id " << id << " not in the dump";
    const std::vector<test::DumpLine>& lines = dump.at(id);
    const nlohmann::json& points = all["evaluation_stage"]["points"];
    ASSERT_EQ(points.size(), lines.size()) << args;
    for (std::size_t k = 0; k < lines.size(); ++k)
      test::expect_same_bits(points[k], lines[k], args + " point " + std::to_string(k));
    const std::size_t last = lines.size() - 1;
    const nlohmann::json one = test::inspect_json(dir, args + " --vertex " + std::to_string(last));
    test::expect_same_bits(one["evaluation_stage"]["points"][0], lines[last], args + " --vertex");
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, InspectDraws,
                         ::testing::Values(Case{"bicubic_arrays.json", 0, {0, 1}}, Case{"terrain.json", 0, {0, 3}},
                                           Case{"grass_isolines.json", 0, {1}}, Case{"dome_points.json", 2, {0, 1}},
                                           Case{"instanced_blocks.json", 0, {0, 5}},
                                           Case{"two_draws_depth.json", 1, {1}}),
                         [](const auto& info) { return info.param.scene.substr(0, info.param.scene.find('.')); });

TEST(InspectDrawsNumbering, CornersAndPatchCarryGlsNumbers) {
  TempDir dir;
  // glDrawArrays(GL_PATCHES, 0, 16) with 4-vertex patches: patch 1's corners are vertices 4..7.
  const nlohmann::json t = test::inspect_json(dir, kDraws + "terrain.json --patch 1");
  const nlohmann::json& corners = t["vertex_stage"]["corners"];
  ASSERT_EQ(corners.size(), 4u);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(corners[k]["gl_VertexID"], 4 + k);
  EXPECT_EQ(corners[2]["inputs"][0]["value"], nlohmann::json({4.0, 0.0, 2.0, 1.0}));  // in_position, w filled in
  // Three instances of two patches: the draw's patch 5 is instance 2's gl_PrimitiveID 1.
  const nlohmann::json i = test::inspect_json(dir, kDraws + "instanced_blocks.json --patch 5");
  EXPECT_EQ(i["draw"]["gl_InstanceID"], 2);
  EXPECT_EQ(i["draw"]["gl_PrimitiveID"], 1);
  EXPECT_EQ(i["draw"]["patch_id"], 5);
  EXPECT_EQ(i["patch_count"], 6);
  // The second draw's patches follow the first draw's (which has none: untessellated triangles).
  const nlohmann::json d = test::inspect_json(dir, kDraws + "two_draws_depth.json --draw 1 --patch 1");
  EXPECT_EQ(d["draw"]["draw"], 1);
  EXPECT_EQ(d["draw"]["patch_id"], 1);
}

TEST(InspectDrawsNumbering, BadRequestsExitTwoNamingTheOption) {
  const struct {
    std::string args, message;
  } cases[] = {
      {"two_draws_depth.json --patch 0", "--draw: required: the scene has 2 draws"},
      {"two_draws_depth.json --draw 2 --patch 0", "--draw: 2 is past the scene's 2 draws (0..1)"},
      {"two_draws_depth.json --draw 0 --patch 0", "--draw: draws.0 draws untessellated primitives, not GL_PATCHES"},
      {"instanced_blocks.json --patch 6", "--patch: 6 is past draws.0, which has 6 patches (0..5"},
      {"terrain.json --pixel 999,3", "--pixel: (999, 3) is off the"},
      {"terrain.json --patch 0 --vertex 289", "--vertex: 289 is past the patch's 289 generated domain points"},
  };
  for (const auto& c : cases) {
    const CliRun r = run_cli("inspect " + kDraws + c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.output;
    EXPECT_THAT(r.output, HasSubstr(c.message)) << c.args;
  }
  const CliRun mesh = run_cli("inspect --draw 0 --patch 0");
  EXPECT_EQ(mesh.exit_code, 2);
  EXPECT_THAT(mesh.output, HasSubstr("--draw: the scene has no draws"));
}

}  // namespace
}  // namespace tessref

namespace tessref {
namespace {

// A scene of draws: the plane (draw 0, untessellated) and the bicubic patches (draw 1) at a pixel
// where the patches lie just behind the plane; every fragment is listed with its draw, the patch's
// own verdict is GL_LESS against the plane's depth, and the replay agrees with the draw.
TEST(InspectDrawsPixel, EachDrawsFragmentsWithTheirStateAndVerdicts) {
  TempDir dir;
  const nlohmann::json j = test::inspect_json(dir, kDraws + "two_draws_depth.json" + " --pixel 128,150");
  const nlohmann::json& f = j["fragments"];
  ASSERT_EQ(f.size(), 2u);
  EXPECT_EQ(f[0]["draw"], 0);
  EXPECT_EQ(f[0]["from_patch"], false);
  EXPECT_EQ(f[0]["triangle"], 0);
  EXPECT_TRUE(f[0]["depth_test"]["passed"].get<bool>());
  EXPECT_EQ(f[1]["draw"], 1);
  EXPECT_EQ(f[1]["patch"], 0);
  EXPECT_EQ(f[1]["triangle"], 189);
  EXPECT_FALSE(f[1]["depth_test"]["passed"].get<bool>());
  EXPECT_EQ(f[1]["depth_test"]["stored_by"], 0);
  EXPECT_EQ(j["winner"], 0);
  EXPECT_EQ(j["pixel_color"], f[0]["color"]);
}

// GL_LEQUAL with depth writes off and blending: the blended plane wins over the patches but leaves
// their depth; the third draw's GL_GREATER fails against it. Four draw buffers: each output is
// listed and every buffer's value is given.
TEST(InspectDrawsPixel, BlendingDepthFunctionsAndDrawBuffers) {
  TempDir dir;
  const nlohmann::json j = test::inspect_json(dir, kDraws + "fixed_function.json" + " --pixel 128,150");
  const nlohmann::json& f = j["fragments"];
  ASSERT_EQ(f.size(), 3u);
  EXPECT_TRUE(f[1]["depth_test"]["passed"].get<bool>());
  EXPECT_EQ(f[1]["depth_test"]["stored_by"], 0);
  EXPECT_FALSE(f[2]["depth_test"]["passed"].get<bool>());
  EXPECT_EQ(f[2]["depth_test"]["stored_by"], 0);  // draw 1 wrote no depth
  EXPECT_EQ(j["winner"], 1);
  EXPECT_NE(j["pixel_color"], f[1]["color"]);  // blended over the patch's colour
  const CliRun text = run_cli("inspect " + kDraws + "fixed_function.json" + " --pixel 128,150");
  EXPECT_EQ(text.exit_code, 0) << text.output;
  EXPECT_THAT(text.output, HasSubstr("depth test: passed: 0.95400703 <= 0.95447892, fragment 0's"));
  EXPECT_THAT(text.output, HasSubstr("depth test: failed: 0.95400703 > 0.95447892, fragment 0's does not hold"));

  const nlohmann::json g = test::inspect_json(dir, kDraws + "attachments.json" + " --pixel 40,150");
  ASSERT_EQ(g["pixel_draw_buffers"].size(), 4u);
  ASSERT_FALSE(g["fragments"].empty());
  EXPECT_EQ(g["fragments"].back()["outputs"].size(), 4u);
}

// Fragment shader traces per draw; --pixel takes no --draw.
TEST(InspectDrawsPixel, TracesAndRefusals) {
  const CliRun traced = run_cli("inspect " + kDraws + "two_draws_depth.json" + " --pixel 128,150 --trace");
  EXPECT_EQ(traced.exit_code, 0) << traced.output;
  EXPECT_THAT(traced.output, HasSubstr("frag_color = vec4(0.5 * normalize(e_normal) + 0.5, 1.0);"));
  EXPECT_THAT(traced.output, HasSubstr("frag_color = u_fill;"));
  const CliRun with_draw = run_cli("inspect " + kDraws + "two_draws_depth.json" + " --pixel 1,1 --draw 0");
  EXPECT_EQ(with_draw.exit_code, 2);
  EXPECT_THAT(with_draw.output, HasSubstr("give --pixel alone"));
}

// Lines and points are followed like triangles: isolines numbered within their patch, with
// gl_TessCoord along the line; GL_LINE_LOOP and GL_POINTS numbered in their draw; polygon mode line
// keeps the triangle; point mode's point at the pixel is the one whose gl_TessCoord the fragment
// shader writes as its colour (dome_points.tese passes the coordinate on), so the tags cannot have
// named another point. Each run also checks that the replay agrees with the frame.
TEST(InspectDrawsPixel, LinesAndPointsAreFollowed) {
  TempDir dir;
  const nlohmann::json grass = test::inspect_json(dir, kDraws + "grass_isolines.json" + " --pixel 48,88");
  ASSERT_EQ(grass["fragments"].size(), 1u);
  const nlohmann::json& blade = grass["fragments"][0];
  EXPECT_EQ(blade["draw"], 0);
  EXPECT_EQ(blade["primitive"], "line");
  EXPECT_EQ(blade["patch"], 1);
  EXPECT_EQ(blade["line"], 29);
  EXPECT_TRUE(blade["from_patch"].get<bool>());

  const nlohmann::json both = test::inspect_json(dir, kDraws + "grass_isolines.json" + " --pixel 10,179");
  ASSERT_EQ(both["fragments"].size(), 2u);
  EXPECT_EQ(both["fragments"][0]["draw"], 1);
  EXPECT_EQ(both["fragments"][0]["primitive"], "line");
  EXPECT_EQ(both["fragments"][0]["line"], 0);
  EXPECT_FALSE(both["fragments"][0]["from_patch"].get<bool>());
  EXPECT_EQ(both["fragments"][1]["draw"], 2);
  EXPECT_EQ(both["fragments"][1]["primitive"], "point");
  EXPECT_EQ(both["fragments"][1]["point"], 1);
  EXPECT_EQ(both["winner"], 1);

  const nlohmann::json wire = test::inspect_json(dir, kDraws + "dome_points.json" + " --pixel 34,99");
  ASSERT_EQ(wire["fragments"].size(), 2u);
  EXPECT_EQ(wire["fragments"][0]["primitive"], "triangle");  // polygon mode GL_LINE
  EXPECT_EQ(wire["fragments"][0]["triangle"], 0);
  EXPECT_FALSE(wire["fragments"][0]["front_facing"].get<bool>());
  EXPECT_EQ(wire["fragments"][1]["primitive"], "line");  // GL_LINE_STRIP
  EXPECT_EQ(wire["winner"], 1);

  const nlohmann::json dome = test::inspect_json(dir, kDraws + "dome_points.json" + " --pixel 119,74");
  ASSERT_EQ(dome["fragments"].size(), 1u);
  const nlohmann::json& point = dome["fragments"][0];
  EXPECT_EQ(point["primitive"], "point");
  EXPECT_EQ(point["patch"], 1);
  EXPECT_EQ(point["point"], 120);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(point["gl_TessCoord"][c], point["outputs"][0][c]) << c;
}

}  // namespace
}  // namespace tessref
