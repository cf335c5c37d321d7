// Phong tessellation, NLSA and Nagata triangles drawn by the GL driver (llvmpipe here) through
// their GLSL twins against tessref's C++ programs: the whole scene's 8-bit images agree on every
// pixel within 2/255 with identical coverage, and the driver's TES outputs (transform feedback)
// give the same patches and gl_TessCoord bits as tessref, with positions and normals within a few
// ulps (LLVM may contract a * b + c into an FMA; see pn_twins_test.cpp). The measured figures are
// printed; on failure the diff image goes to the build directory.
#include <algorithm>
#include <bit>
#include <cstdio>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "gl_fixture.h"
#include "glref/scene_renderer.h"
#include "io/image_compare.h"
#include "io/image_output.h"
#include "mesh/mesh_source.h"
#include "render/render.h"
#include "scene/scene_loader.h"

namespace tessref::glref {
namespace {

constexpr int kTolerance = 2;  // 1/255 steps, on every pixel
// World positions (|p| < 2 here) and unit normals: the PN twins' bounds (pn_twins_test.cpp).
constexpr float kPositionTolerance = 1.5e-6f;
constexpr float kNormalTolerance = 2.5e-6f;

std::vector<std::string> scheme_scene(const std::string& scheme, std::vector<std::string> more = {}) {
  std::vector<std::string> sets{"tessellation.enabled=true", "tessellation.scheme=" + scheme,
                                "tessellation.inner=12", "tessellation.outer=12",
                                "image.width=512", "image.height=512"};
  sets.insert(sets.end(), more.begin(), more.end());
  return sets;
}

std::string joined(const std::vector<std::string>& sets) {
  std::string s;
  for (const std::string& x : sets) s += (s.empty() ? "" : " ") + x;
  return s;
}

void expect_images_match(GlContext& ctx, const std::string& name, const std::vector<std::string>& sets) {
  const auto [ours, gl] = testing::draw_both(ctx, sets);
  const ImageComparison c = compare_framebuffers(ours.framebuffer, gl, kTolerance, true);
  std::printf("[ figures  ] %s: %s\n", name.c_str(), c.summary().c_str());
  if (c.within_tolerance != c.pixels || c.coverage_mismatch != 0) {
    const std::string base = std::string(TESSREF_BINARY_DIR) + "/schemes_vs_llvmpipe_" + name;
    write_rgb8_image(c.diff, base + "_diff.png");
    std::printf("[ figures  ] wrote %s_diff.png\n", base.c_str());
  }
  EXPECT_EQ(c.within_tolerance, c.pixels) << joined(sets) << ": " << c.summary();
  EXPECT_EQ(c.coverage_mismatch, 0u) << joined(sets) << ": " << c.summary();
  EXPECT_GT(ours.stats.raster.fragments_shaded, 50000u) << joined(sets);
}

void expect_tess_outputs_match(GlContext& ctx, const std::vector<std::string>& sets) {
  const Scene scene = load_scene("", sets);
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  std::vector<TessDumpRecord> records;
  DrawOptions options;
  options.dump_tess = [&](const std::vector<TessDumpRecord>& r) { records.insert(records.end(), r.begin(), r.end()); };
  render_scene(scene, mesh, Parallel(), options);
  std::map<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t>, const TessDumpRecord*> by_coord;
  for (const TessDumpRecord& r : records)
    by_coord.emplace(std::make_tuple(r.patch_id, std::bit_cast<std::uint32_t>(r.tess_coord.x),
                                     std::bit_cast<std::uint32_t>(r.tess_coord.y),
                                     std::bit_cast<std::uint32_t>(r.tess_coord.z)),
                     &r);
  SceneRenderer renderer(ctx, scene, mesh);
  const std::vector<TessOutputVertex> gl = renderer.capture_tess();
  ASSERT_FALSE(gl.empty());
  float pos_err = 0.0f, nrm_err = 0.0f;
  for (std::size_t k = 0; k < gl.size(); ++k) {
    const auto it = by_coord.find(std::make_tuple(gl[k].patch, std::bit_cast<std::uint32_t>(gl[k].tess_coord.x),
                                                  std::bit_cast<std::uint32_t>(gl[k].tess_coord.y),
                                                  std::bit_cast<std::uint32_t>(gl[k].tess_coord.z)));
    ASSERT_NE(it, by_coord.end()) << "vertex " << k << ": a tess coord tessref never generated";
    const glm::vec3 dp = glm::abs(gl[k].position - it->second->position);
    const glm::vec3 dn = glm::abs(gl[k].normal - it->second->normal);
    pos_err = std::max({pos_err, dp.x, dp.y, dp.z});
    nrm_err = std::max({nrm_err, dn.x, dn.y, dn.z});
  }
  std::printf("[ figures  ] %s: %zu TES outputs, max |position error| %.3g, max |normal error| %.3g\n",
              joined(sets).c_str(), gl.size(), pos_err, nrm_err);
  EXPECT_LE(pos_err, kPositionTolerance) << joined(sets);
  EXPECT_LE(nrm_err, kNormalTolerance) << joined(sets);
}

class SchemesVsLlvmpipe : public ::testing::TestWithParam<std::tuple<const char*, const char*>> {};

TEST_P(SchemesVsLlvmpipe, ImagesAndTessOutputs) {
  TESSREF_REQUIRE_GL(ctx);
  const auto [scheme, mode] = GetParam();
  const std::vector<std::string> sets = scheme_scene(scheme, {std::string("tessellation.normal_mode=") + mode});
  expect_images_match(*ctx, std::string(scheme) + "_" + mode, sets);
  expect_tess_outputs_match(*ctx, sets);
}

INSTANTIATE_TEST_SUITE_P(AllSchemesAndModes, SchemesVsLlvmpipe,
                         ::testing::Combine(::testing::Values("phong", "nlsa", "nagata"),
                                            ::testing::Values("linear", "quadratic", "quadratic_corrected",
                                                              "analytic")),
                         [](const auto& info) {
                           return std::string(std::get<0>(info.param)) + "_" + std::get<1>(info.param);
                         });

TEST(SchemesVsLlvmpipeParameters, AlphaEpsAdaptiveAndAnotherMesh) {
  TESSREF_REQUIRE_GL(ctx);
  const std::vector<std::vector<std::string>> cases = {
      scheme_scene("phong", {"tessellation.phong_alpha=0.3", "tessellation.spacing=equal"}),
      scheme_scene("nagata", {"tessellation.nagata_eps=0", "tessellation.adaptive.enabled=true"}),
      scheme_scene("nagata", {"tessellation.nagata_eps=0.04"}),
      scheme_scene("nlsa", {"mesh.type=icosphere", "tessellation.spacing=fractional_even",
                            "tessellation.inner=5.5", "tessellation.outer=5.5"}),
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    expect_images_match(*ctx, "params" + std::to_string(i), cases[i]);
    expect_tess_outputs_match(*ctx, cases[i]);
  }
}

}  // namespace
}  // namespace tessref::glref
