// `tessref capture` and `tessref verify` on scenes of draws (tests/data/draws): the user's shaders
// wrapped, not read; gl_TessCoord streams and gl_Position compared patch by patch, with GL's patch
// numbering over calls and instances; the silhouette from what the program outputs. Each scene
// passes against llvmpipe, and a planted fault in a capture is caught and located.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../pipeline/test_util.h"
#include "gl_fixture.h"
#include "io/tess_dump.h"

namespace tessref {
namespace {

using ::testing::HasSubstr;

struct DrawScene {
  const char* name;
  std::uint64_t patches;  // in the capture's records
  std::uint64_t emitted;
  bool silhouette;        // examined (every depth-writing draw fills triangles)
};

const DrawScene kScenes[] = {
    {"bicubic_arrays", 2, 1728, true},   // 16-vertex bicubic patches, glDrawArrays
    {"terrain", 4, 6144, true},          // quad patches with a height map sampled in the TES
    {"grass_isolines", 2, 960, false},   // isolines, then a line loop and points
    {"dome_points", 2, 384, false},      // point mode
    {"instanced_blocks", 6, 2304, true}, // instanced, indexed, std140 block at an offset
    {"two_draws_depth", 2, 1728, true},  // tessellated, depth-tested against an untessellated strip
    {"fixed_function", 2, 1728, false},  // culling under GL_CW, blending, scissor
    {"viewports", 4, 3456, false},       // a viewport and depth range per draw
    {"storage_blocks", 2, 1728, true},   // vertex pulling and a patch parameter from storage blocks
};

class DrawsCaptureVsLlvmpipe : public ::testing::TestWithParam<DrawScene> {
 protected:
  void SetUp() override { TESSREF_REQUIRE_GL(ctx); }
};

TEST_P(DrawsCaptureVsLlvmpipe, CapturedAndVerified) {
  const DrawScene& s = GetParam();
  const test::TempDir dir;
  const std::string scene = std::string(TESSREF_SOURCE_DIR) + "/tests/data/draws/" + s.name + ".json";
  const std::string ref = (dir.path() / "ref").string(), json = (dir.path() / "v.json").string();
  const test::CliRun capture = test::run_cli("capture " + scene + " --out " + ref);
  ASSERT_EQ(capture.exit_code, 0) << capture.output;
  EXPECT_THAT(capture.output, HasSubstr("tess.bin (" + std::to_string(s.emitted) + " emitted vertices)"));
  std::ifstream in(ref + "/manifest.json");
  EXPECT_THAT(nlohmann::json::parse(in)["tess_values"].get<std::string>(), HasSubstr("gl_Position"));

  const test::CliRun verify = test::run_cli("verify " + scene + " --ref " + ref + " --json " + json);
  EXPECT_EQ(verify.exit_code, 0) << verify.output;
  std::ifstream report(json);
  const nlohmann::json j = nlohmann::json::parse(report);
  EXPECT_EQ(j["tessellation"]["patches"], s.patches);
  EXPECT_EQ(j["tessellation"]["patches_mismatched"], 0);
  EXPECT_EQ(j["tessellation"]["unmatched_vertices"], 0);
  EXPECT_EQ(j["tessellation"]["emitted_vertices"], s.emitted);
  // Every scene here is identical to llvmpipe in coverage, and within 1/255 in colour.
  EXPECT_EQ(j["coverage"]["mismatched"], 0);
  EXPECT_EQ(j["color"]["within_1_255"], j["color"]["pixels"]);
  EXPECT_EQ(j["silhouette"]["examined"], s.silhouette) << j["silhouette"].dump();
  if (s.silhouette) {
    EXPECT_EQ(j["silhouette"]["beyond_limit"], 0);
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, DrawsCaptureVsLlvmpipe, ::testing::ValuesIn(kScenes),
                         [](const auto& info) { return std::string(info.param.name); });

// One gl_TessCoord moved by one ULP in the grass's second patch is found there.
TEST(DrawsCaptureFaults, OneUlpInOnePatchIsLocated) {
  TESSREF_REQUIRE_GL(ctx);
  const test::TempDir dir;
  const std::string scene = std::string(TESSREF_SOURCE_DIR) + "/tests/data/draws/grass_isolines.json";
  const std::string ref = (dir.path() / "ref").string();
  ASSERT_EQ(test::run_cli("capture " + scene + " --out " + ref).exit_code, 0);
  std::vector<TessDumpRecord> records = read_tess_dump(ref + "/tess.bin");
  ASSERT_FALSE(records.empty());
  auto it = std::find_if(records.begin(), records.end(), [](const TessDumpRecord& r) { return r.patch_id == 1; });
  ASSERT_NE(it, records.end());
  it->tess_coord.x = std::nextafter(it->tess_coord.x, 2.0f);
  TessDumpWriter writer(ref + "/tess.bin");
  writer.write(records);
  writer.close();
  const test::CliRun r = test::run_cli("verify " + scene + " --ref " + ref);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("gl_TessCoord streams differ in 1 of 2 patches (first: patch 1)"));
}

}  // namespace
}  // namespace tessref
