// Every scene under scenes/ against its committed llvmpipe capture (tests/data/captures, made by
// scripts/capture-scenes.sh): no GL driver is needed to run this, only tessref and Embree. The
// issue's bar: gl_TessCoord streams identical (every patch, by digest; the sampled patches record
// by record), the two surfaces within 1e-5 of the bounding-box diagonal both ways, and coverage
// mismatches only at pixel centres within half a pixel of the silhouette.
#include <filesystem>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../pipeline/test_util.h"

namespace tessref {
namespace {

class CommittedCaptures : public ::testing::TestWithParam<const char*> {};

TEST_P(CommittedCaptures, SceneVerifies) {
  const std::string name = GetParam();
  const std::string source = TESSREF_SOURCE_DIR;
  const std::string scene = source + "/scenes/" + name + ".json";
  const std::string ref = source + "/tests/data/captures/" + name;
  if (name == "spider" || name == "wuson_pn64") {
    if (!std::filesystem::exists("/usr/share/assimp/models/OBJ/spider.obj"))
      GTEST_SKIP() << "assimp-testmodels is not installed (scripts/install-deps.sh installs it)";
  }
  test::TempDir dir;
  const std::string report = (dir.path() / "report.json").string();
  const test::CliRun r = test::run_cli("verify " + scene + " --ref " + ref +
                                       " --set image.width=256 --set image.height=256 --json " + report);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, ::testing::Not(::testing::HasSubstr("warning: " + ref + " was captured from another scene")));
  std::ifstream in(report);
  const nlohmann::json j = nlohmann::json::parse(in);
  const auto& t = j["tessellation"];
  EXPECT_GT(t["patches"].get<int>(), 0);
  EXPECT_EQ(t["patches_mismatched"], 0);
  EXPECT_EQ(t["unmatched_vertices"], 0);
  EXPECT_GT(t["records_compared"].get<int>(), 0);
  EXPECT_EQ(t["order_differs_patches"], 0);  // llvmpipe emits in tessref's order
  EXPECT_LT(j["surface_distance"]["hausdorff_of_diagonal"].get<double>(), 1e-5);
  EXPECT_EQ(j["silhouette"]["beyond_limit"], 0);
  EXPECT_LE(j["silhouette"]["max_distance_px"].get<double>(), 0.5);
  EXPECT_EQ(j["cracks"]["rays_through"], 0);
}

INSTANTIATE_TEST_SUITE_P(Scenes, CommittedCaptures,
                         ::testing::Values("default", "displacement", "spider", "wuson_pn64"),
                         [](const auto& info) { return std::string(info.param); });

}  // namespace
}  // namespace tessref
