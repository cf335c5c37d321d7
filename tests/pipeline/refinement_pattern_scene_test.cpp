// tessellation.tessellator = "refinement_pattern" through the pipeline and the CLI: the
// tessellated torus is watertight (every point on a patch's boundary is the same bits in the
// neighbouring patch), level 1 is the primitive generator's drawing, the counts follow the level of
// detail, compare-tessellators reports the pattern beside the uniform grid, and the scene keys
// refuse what is not plumbed.
#include <gtest/gtest.h>

#include <cstring>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/error.h"
#include "mesh/mesh_source.h"
#include "render/render.h"
#include "scene/scene_loader.h"
#include "test_util.h"
#include "twins_test_util.h"

namespace tessref {
namespace {

using test::Frame;

Frame render(std::vector<std::string> sets) {
  sets.insert(sets.end(), {"image.width=128", "image.height=128"});
  return test::render_frame(sets);
}

std::vector<std::string> rp(float level) {
  const std::string l = std::to_string(level);
  return {"tessellation.tessellator=refinement_pattern", "tessellation.inner=" + l, "tessellation.outer=" + l};
}

TEST(RefinementPatternScene, SharedEdgesAreWatertight) {
  // The default torus is closed: every boundary point of a patch lies on an edge shared with one
  // other patch, so its position (bits) must come from at least two patches.
  for (const char* mode : {"linear", "quadratic"}) {
    std::vector<std::string> sets = rp(8.0f);
    sets.push_back(std::string("tessellation.normal_mode=") + mode);
    const Frame f = render(sets);
    std::map<std::array<std::uint32_t, 6>, std::set<std::uint32_t>> at;
    std::size_t boundary = 0;
    for (const TessDumpRecord& r : f.dump)
      if (r.tess_coord.x == 0.0f || r.tess_coord.y == 0.0f || r.tess_coord.z == 0.0f) {
        std::array<std::uint32_t, 6> key;
        std::memcpy(key.data(), &r.position, 12);
        std::memcpy(key.data() + 3, &r.normal, 12);  // the shading normal matches too
        at[key].insert(r.patch_id);
        ++boundary;
      }
    // 256 patches, 3 * 8 boundary points each.
    EXPECT_EQ(boundary, 256u * 24u) << mode;
    std::size_t lonely = 0;
    for (const auto& [key, patches] : at) lonely += patches.size() < 2;
    EXPECT_EQ(lonely, 0u) << mode << ": boundary points found in one patch only";
  }
}

TEST(RefinementPatternScene, CountsAndLevelOne) {
  const Frame five = render(rp(5.0f));
  EXPECT_EQ(five.stats.triangles_generated, 256u * 64u);  // RP_3
  EXPECT_EQ(five.stats.tess.domain_points, 256u * 45u);
  const Frame one = render(rp(1.0f)), tpg = render({"tessellation.inner=1", "tessellation.outer=1"});
  ASSERT_EQ(one.dump.size(), tpg.dump.size());
  EXPECT_EQ(std::memcmp(one.dump.data(), tpg.dump.data(), one.dump.size() * sizeof(TessDumpRecord)), 0);
  EXPECT_EQ(std::memcmp(one.fb.color.data(), tpg.fb.color.data(), one.fb.color.size() * sizeof(one.fb.color[0])), 0);
}

TEST(RefinementPatternScene, SceneKeysRefuseWhatIsNotPlumbed) {
  for (const std::vector<std::string>& sets :
       {std::vector<std::string>{"tessellation.tessellator=refinement_pattern", "tessellation.adaptive.enabled=true"},
        std::vector<std::string>{"tessellation.tessellator=refinement_pattern", "shaders.program=twins"}}) {
    try {
      load_scene("", sets);
      ADD_FAILURE() << sets[1] << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("tessellation.tessellator"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("refinement_pattern"), std::string::npos) << e.what();
    }
  }
}

TEST(RefinementPatternScene, CompareTessellatorsReportsIt) {
  test::TempDir dir;
  const auto json = dir.path() / "r.json";
  const test::CliRun r = test::run_cli("compare-tessellators --set image.width=96 --set image.height=96 --levels 1,3 "
                                       "--json " + json.string() + " --images " + (dir.path() / "img").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = nlohmann::json::parse(test::read_file(json));
  const nlohmann::json& one = j["levels"][0]["refinement_pattern"];
  EXPECT_EQ(one["lod"], 0);
  EXPECT_EQ(one["hausdorff_of_diagonal"], 0.0);
  EXPECT_EQ(one["coverage"]["differs"], 0);
  EXPECT_EQ(one["colour_differs"], 0);
  const nlohmann::json& three = j["levels"][1]["refinement_pattern"];
  EXPECT_EQ(three["segments"], 4);
  EXPECT_EQ(three["triangles_per_patch"], 16);
  EXPECT_EQ(three["triangles"], 256 * 16);
  EXPECT_GT(three["hausdorff_of_diagonal"].get<double>(), 0.0);
  for (const char* name : {"refinement-3.png", "coverage-refinement-3.png"})
    EXPECT_TRUE(std::filesystem::is_regular_file(dir.path() / "img" / name)) << name;
}

}  // namespace
}  // namespace tessref
