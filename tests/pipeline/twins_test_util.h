#pragma once
// Helpers of the tests that run the built-in programs' GLSL twins on tessref's executor against
// the C++ programs (shaders.program = twins against builtin), and of the scene tests that compare
// draws by their tessellation dump.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "mesh/mesh_source.h"
#include "render/render.h"
#include "scene/scene_loader.h"

namespace tessref::test {

struct Frame {
  Framebuffer fb;
  std::vector<TessDumpRecord> dump;
  DrawStats stats;
};

// The default scene with the --set overrides `sets`, drawn on `threads` threads: its image, every
// TES invocation's record and the draw's statistics.
inline Frame render_frame(const std::vector<std::string>& sets, int threads = 2) {
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

inline Frame render(std::vector<std::string> sets, int threads = 2) {
  sets.push_back("image.width=256");
  sets.push_back("image.height=256");
  return render_frame(sets, threads);
}

inline std::vector<std::string> with(std::vector<std::string> sets, const std::string& more) {
  sets.push_back(more);
  return sets;
}

// Images: identical coverage (where depth was written), every color channel within 1/255, and
// the count of differing pixels for the message.
inline void expect_equivalent(const Frame& cpp, const Frame& twins, const std::string& what) {
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

// How many dump records differ in their bytes (the two dumps expected the same length).
inline std::size_t differing_records(const Frame& a, const Frame& b) {
  EXPECT_EQ(a.dump.size(), b.dump.size());
  std::size_t n = 0;
  for (std::size_t i = 0; i < std::min(a.dump.size(), b.dump.size()); ++i)
    n += std::memcmp(&a.dump[i], &b.dump[i], sizeof(TessDumpRecord)) != 0;
  return n;
}

// gl_TessCoord and patch ids identical; positions and normals bit for bit (0 ULP: the twins follow
// the C++ programs' operations in order, and the executor rounds each one as C++ does).
inline void expect_same_dump(const Frame& cpp, const Frame& twins, const std::string& what) {
  ASSERT_EQ(cpp.dump.size(), twins.dump.size()) << what;
  ASSERT_FALSE(cpp.dump.empty()) << what;
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i < cpp.dump.size(); ++i)
    mismatches += std::memcmp(&cpp.dump[i], &twins.dump[i], sizeof(TessDumpRecord)) != 0;
  EXPECT_EQ(mismatches, 0u) << what << ": records differ";
}

}  // namespace tessref::test
