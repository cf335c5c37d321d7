// The built-in programs' GLSL twins on tessref's executor against the C++ programs they mirror
// (shaders.program = twins against builtin): the same coverage, colors within 1/255, and the same
// gl_TessCoord, positions and normals bit for bit; and the executor's output does not depend on
// the thread count nor on its batch size.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "pipeline/mesh_source.h"
#include "pipeline/render.h"
#include "pipeline/scene_loader.h"

namespace tessref {
namespace {

struct Frame {
  Framebuffer fb;
  std::vector<TessDumpRecord> dump;
  DrawStats stats;
};

Frame render(std::vector<std::string> sets, int threads = 2) {
  sets.push_back("image.width=256");
  sets.push_back("image.height=256");
  const Scene scene = load_scene("", sets);
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  Frame f;
  DrawOptions options;
  options.dump_tess = [&](const std::vector<TessDumpRecord>& r) { f.dump.insert(f.dump.end(), r.begin(), r.end()); };
  RenderResult r = render_scene(scene, mesh, Parallel(threads), options);
  f.fb = std::move(r.framebuffer);
  f.stats = r.stats;
  return f;
}

std::vector<std::string> with(std::vector<std::string> sets, const std::string& more) {
  sets.push_back(more);
  return sets;
}

// Images: identical coverage (where depth was written), every color channel within 1/255, and
// the count of differing pixels for the message.
void expect_equivalent(const Frame& cpp, const Frame& twins, const std::string& what) {
  ASSERT_EQ(cpp.fb.color.size(), twins.fb.color.size());
  std::size_t covered = 0, coverage_mismatch = 0, over = 0, differ = 0;
  for (std::size_t i = 0; i < cpp.fb.color.size(); ++i) {
    const bool a = cpp.fb.depth[i] < 1.0f, b = twins.fb.depth[i] < 1.0f;
    covered += a;
    coverage_mismatch += a != b;
    float worst = 0.0f;
    for (int c = 0; c < 4; ++c) worst = std::max(worst, std::fabs(cpp.fb.color[i][c] - twins.fb.color[i][c]));
    over += worst > 1.0f / 255.0f;
    differ += worst > 0.0f;
  }
  EXPECT_GT(covered, 1000u) << what;
  EXPECT_EQ(coverage_mismatch, 0u) << what;
  EXPECT_EQ(over, 0u) << what << ": " << differ << " pixels differ at all";
  EXPECT_EQ(cpp.stats.raster.fragments_shaded, twins.stats.raster.fragments_shaded) << what;
}

// gl_TessCoord and patch ids identical; positions and normals bit for bit (0 ULP: the twins follow
// the C++ programs' operations in order, and the executor rounds each one as C++ does).
void expect_same_dump(const Frame& cpp, const Frame& twins, const std::string& what) {
  ASSERT_EQ(cpp.dump.size(), twins.dump.size()) << what;
  ASSERT_FALSE(cpp.dump.empty()) << what;
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i < cpp.dump.size(); ++i)
    mismatches += std::memcmp(&cpp.dump[i], &twins.dump[i], sizeof(TessDumpRecord)) != 0;
  EXPECT_EQ(mismatches, 0u) << what << ": records differ";
}

TEST(GlslTwins, DefaultSceneMatchesTheCppProgramsInEveryNormalMode) {
  for (const char* mode : {"linear", "quadratic", "quadratic_corrected", "analytic"}) {
    const std::vector<std::string> sets = {std::string("tessellation.normal_mode=") + mode};
    const Frame cpp = render(sets);
    const Frame twins = render(with(sets, "shaders.program=twins"));
    expect_equivalent(cpp, twins, mode);
    expect_same_dump(cpp, twins, mode);
  }
}

TEST(GlslTwins, FlatSchemeNormalsShadingAndNoTessellation) {
  const std::vector<std::vector<std::string>> cases = {
      {"tessellation.scheme=flat"},
      {"shading=normals", "tessellation.spacing=equal", "tessellation.winding=cw"},
      {"tessellation.enabled=false"},
      {"tessellation.adaptive.enabled=true"},
  };
  for (const auto& sets : cases) {
    const std::string what = sets[0];
    const Frame cpp = render(sets);
    const Frame twins = render(with(sets, "shaders.program=twins"));
    expect_equivalent(cpp, twins, what);
    if (!cpp.dump.empty()) expect_same_dump(cpp, twins, what);
  }
}

TEST(GlslTwins, ImagesAndDumpsDoNotDependOnThreadsOrBatchSize) {
  const std::vector<std::string> sets = {"shaders.program=twins"};
  const Frame base = render(with(sets, "shaders.batch_lanes=256"), 1);
  for (int threads : {1, 2, 8})
    for (int lanes : {1, 7, 64, 256}) {
      if (threads == 1 && lanes == 256) continue;
      const Frame f = render(with(sets, "shaders.batch_lanes=" + std::to_string(lanes)), threads);
      const std::string what = std::to_string(threads) + " threads, batch " + std::to_string(lanes);
      EXPECT_EQ(0, std::memcmp(base.fb.color.data(), f.fb.color.data(), base.fb.color.size() * sizeof(glm::vec4))) << what;
      EXPECT_EQ(0, std::memcmp(base.fb.depth.data(), f.fb.depth.data(), base.fb.depth.size() * sizeof(float))) << what;
      ASSERT_EQ(base.dump.size(), f.dump.size()) << what;
      EXPECT_EQ(0, std::memcmp(base.dump.data(), f.dump.data(), base.dump.size() * sizeof(TessDumpRecord))) << what;
    }
}

}  // namespace
}  // namespace tessref
