// tessref inspect: the values it shows are the draw's own (issue 10's first acceptance test): the
// world positions and normals of a patch equal bit for bit what `render --dump-tess` records for
// the same patch and gl_TessCoord; the primitive generator summary follows docs/tpg.md; bad
// requests are refused with exit status 2 and a message naming the option.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/tess_dump.h"
#include "stages/tpg.h"
#include "tess_dump_text.h"
#include "test_util.h"

namespace tessref {
namespace {

using ::testing::HasSubstr;
using test::CliRun;
using test::bits;
using test::DumpLine;
using test::expect_same_bits;
using test::inspect_json;
using test::render_dump;
using test::run_cli;
using test::TempDir;

void expect_patch_matches_dump(const std::string& sets, const std::vector<int>& patches) {
  TempDir dir;
  const auto dump = render_dump(dir, sets);
  ASSERT_EQ(dump.size(), 256u);
  for (int patch : patches) {
    const std::vector<DumpLine>& lines = dump.at(patch);
    ASSERT_FALSE(lines.empty()) << "patch " << patch;
    const std::string p = "--patch " + std::to_string(patch) + sets;
    // Every generated point (no --coord, no --vertex), in generation order.
    const nlohmann::json all = inspect_json(dir, p);
    ASSERT_EQ(all["evaluation_stage"]["points"].size(), lines.size()) << "patch " << patch;
    EXPECT_EQ(all["primitive_generator"]["domain_points"], lines.size());
    for (std::size_t k = 0; k < lines.size(); ++k)
      expect_same_bits(all["evaluation_stage"]["points"][k], lines[k], "patch " + std::to_string(patch) + " point " + std::to_string(k));
    // --coord (evaluated on its own through the TES's batch entry point) and --vertex.
    for (std::size_t k : {std::size_t(0), std::min<std::size_t>(5, lines.size() - 1), lines.size() / 2, lines.size() - 1}) {
      const DumpLine& d = lines[k];
      const nlohmann::json at = inspect_json(dir, p + " --coord " + d.u + "," + d.v + "," + d.w);
      ASSERT_EQ(at["evaluation_stage"]["points"].size(), 1u);
      EXPECT_EQ(at["evaluation_stage"]["points"][0]["index"], k);
      expect_same_bits(at["evaluation_stage"]["points"][0], d, "patch " + std::to_string(patch) + " --coord of point " + std::to_string(k));
      const nlohmann::json vk = inspect_json(dir, p + " --vertex " + std::to_string(k));
      expect_same_bits(vk["evaluation_stage"]["points"][0], d, "patch " + std::to_string(patch) + " --vertex " + std::to_string(k));
    }
  }
}

TEST(Inspect, PositionsAndNormalsAreTheDrawsBitForBit) {
  expect_patch_matches_dump(" --set image.width=128 --set image.height=128", {0, 17, 131, 255});
}

TEST(Inspect, OtherNormalModesSchemesAndAdaptiveLevelsMatchTheDraw) {
  expect_patch_matches_dump(" --set image.width=64 --set image.height=64 --set tessellation.normal_mode=analytic", {42});
  expect_patch_matches_dump(" --set image.width=64 --set image.height=64 --set tessellation.scheme=flat", {42});
  // Screen-space levels: the control shader sees the render's viewport (the image size) and camera.
  expect_patch_matches_dump(" --set image.width=512 --set image.height=384 --set tessellation.adaptive.enabled=true", {42, 100});
}

TEST(Inspect, GlslTwinsOnTheExecutorMatchTheirDraw) {
  expect_patch_matches_dump(" --set image.width=64 --set image.height=64 --set shaders.program=twins", {3, 200});
}

TEST(Inspect, CoordinateOffThePatternIsEvaluated) {
  TempDir dir;
  const nlohmann::json j = inspect_json(dir, "--patch 7 --coord 0.3,0.3");
  const nlohmann::json& p = j["evaluation_stage"]["points"][0];
  EXPECT_TRUE(p["index"].is_null());
  EXPECT_EQ(bits(p["gl_TessCoord"][2]), std::bit_cast<std::uint32_t>((1.0f - 0.3f) - 0.3f));
  // The control shader's output and levels are the built-in PN program's: 3 corners, 12 everywhere.
  EXPECT_EQ(j["control_stage"]["gl_out"].size(), 3u);
  EXPECT_EQ(j["control_stage"]["gl_TessLevelOuter"][0], 12.0);
  const CliRun text = run_cli("inspect --patch 7 --vertex 3");
  EXPECT_EQ(text.exit_code, 0) << text.output;
  EXPECT_THAT(text.output, HasSubstr("b111 (centre)"));
  EXPECT_THAT(text.output, HasSubstr("point 3: gl_TessCoord"));
}

// fractional_odd 12.3: clamped to 12.3, rounded up to the odd 13 segments (docs/tpg.md); the counts
// are the generator's for those levels, and each outer edge holds segments + 1 generated points.
TEST(Inspect, PrimitiveGeneratorSummaryFollowsTheSpacingRules) {
  TempDir dir;
  const nlohmann::json j =
      inspect_json(dir, "--patch 9 --set tessellation.outer=12.3 --set tessellation.inner=12.3");
  const nlohmann::json& t = j["primitive_generator"];
  EXPECT_EQ(t["spacing"], "fractional_odd");
  for (int e = 0; e < 3; ++e) {
    EXPECT_EQ(bits(t["outer_clamped"][e]), std::bit_cast<std::uint32_t>(12.3f));
    EXPECT_EQ(t["outer_segments"][e], 13);
  }
  EXPECT_EQ(t["inner_segments"][0], 13);
  EXPECT_EQ(t["rings"], 7);

  const TessLevels levels{{12.3f, 12.3f, 12.3f, 1.0f}, {12.3f, 1.0f}};
  const TessDomainPoints g = generate_tessellation(
      TessLayout{TessDomain::Triangles, TessSpacing::FractionalOdd, TessWinding::Ccw, false}, levels);
  EXPECT_EQ(t["domain_points"], g.coords.size());
  EXPECT_EQ(t["primitives"], g.primitive_count());
  // And as `tessref tpg` prints them: one line per emitted vertex, three per triangle.
  const CliRun tpg = run_cli("tpg --spacing fractional_odd --outer 12.3,12.3,12.3 --inner 12.3");
  ASSERT_EQ(tpg.exit_code, 0) << tpg.output;
  std::size_t lines = 0;
  for (char c : tpg.output) lines += c == '\n';
  EXPECT_EQ(t["primitives"].get<std::size_t>() * 3, lines);

  // Edge u = 0 is outer[0], v = 0 outer[1], w = 0 outer[2]: segments + 1 points on each.
  int on_edge[3] = {};
  for (const auto& p : j["evaluation_stage"]["points"])
    for (int c = 0; c < 3; ++c) on_edge[c] += p["gl_TessCoord"][c] == 0.0;
  for (int c = 0; c < 3; ++c) EXPECT_EQ(on_edge[c], 14) << "edge " << c;
}

TEST(Inspect, BadRequestsExitTwoNamingTheOption) {
  struct Case {
    std::string args, message;
  } cases[] = {
      {"--patch 256", "--patch: 256 is past the draw, which has 256 patches (0..255)"},
      {"--patch 0 --coord 0.5,0.5,0.5", "--coord: a triangle patch's gl_TessCoord has u + v + w = 1"},
      {"--patch 0 --coord -0.5,1,0.5", "--coord: every component must lie in [0, 1], got U = -0.5"},
      // Issue 24, defect 5: a W the user did not type is named as computed; -1 is not "missing".
      {"--patch 0 --coord 0.7,0.7",
       "--coord: U + V must be at most 1 on a triangle patch: W = (1 - U) - V = -0.399999976 (computed from the U,V given)"},
      {"--patch -1", "--patch: -1 is not a patch: patches count from 0"},
      {"--patch 0 --vertex -1", "--vertex: must be 0 or more, got -1"},
      {"--patch 0 --coord 0.5,x", "--coord: expected U,V[,W]"},
      {"--patch 0 --coord 0.1,0.2,0.3,0.4", "--coord: expected 2 or 3 components"},
      {"--patch 0 --vertex 147", "--vertex: 147 is past the patch's 147 generated domain points"},
      {"--patch 0 --vertex 2 --coord 0.2,0.2,0.6", "--coord and --vertex: give one of them"},
      {"--patch 0 --set tessellation.enabled=false", "the scene does not tessellate"},
  };
  for (const Case& c : cases) {
    const CliRun r = run_cli("inspect " + c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.output;
    EXPECT_THAT(r.output, HasSubstr(c.message)) << c.args;
  }
  const CliRun missing = run_cli("inspect --coord 0.2,0.2,0.6");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_THAT(missing.output, HasSubstr("--patch: required"));
}

}  // namespace
}  // namespace tessref
