// tessellation.tessellator = "uniform" through the whole pipeline: deterministic bytes for any
// thread count and chunk size, the same image and surface as the primitive generator at level 1,
// the distance between the two surfaces shrinking as the level grows (the torus of seed 000's
// Figure 14), and the scene keys' refusals. Here rather than tests/pipeline for the Embree
// distance of verify/ (test_verify links tessref_verify).
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "common/error.h"
#include "mesh/mesh_source.h"
#include "render/render.h"
#include "scene/scene_loader.h"
#include "verify/surface.h"
#include "verify/surface_distance.h"

namespace tessref {
namespace {

struct Drawn {
  std::vector<unsigned char> color, depth;
  TessSurface surface;
  DrawStats stats;
};

// The default scene (the PN torus, fractional_odd) at `level`, small so that the test is quick.
Drawn draw(const std::string& tessellator, float level, int threads = 2, std::size_t chunk = 0) {
  const std::string l = std::to_string(level);
  const Scene scene = load_scene("", {"tessellation.tessellator=" + tessellator, "tessellation.inner=" + l,
                                      "tessellation.outer=" + l, "image.width=160", "image.height=160"});
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  Drawn d;
  DrawOptions options;
  options.tess_chunk_patches = chunk;
  options.tess_surface = [&](const std::vector<TessDumpRecord>& r, const TriangleBatch& b) { d.surface.append(r, b); };
  const RenderResult result = render_scene(scene, mesh, Parallel(threads), options);
  const auto* c = reinterpret_cast<const unsigned char*>(result.framebuffer.color.data());
  d.color.assign(c, c + result.framebuffer.color.size() * sizeof(glm::vec4));
  const auto* z = reinterpret_cast<const unsigned char*>(result.framebuffer.depth.data());
  d.depth.assign(z, z + result.framebuffer.depth.size() * sizeof(float));
  d.stats = result.stats;
  return d;
}

bool same_records(const TessSurface& a, const TessSurface& b) {
  return a.indices == b.indices && a.points.size() == b.points.size() &&
         std::memcmp(a.points.data(), b.points.data(), a.points.size() * sizeof(TessDumpRecord)) == 0;
}

double relative_hausdorff(const TessSurface& a, const TessSurface& b) {
  const Parallel parallel(2);
  const SurfaceOracle oa(a), ob(b);
  return surface_distance(a, oa, b, ob, parallel).hausdorff / a.diagonal();
}

TEST(UniformTessellator, DeterministicForAnyThreadCountAndChunk) {
  const Drawn one = draw("uniform", 7.0f, 1, 0);
  EXPECT_EQ(one.stats.tess.triangles_out, 256u * 49u);  // the torus has 256 triangles
  EXPECT_EQ(one.stats.tess.domain_points, 256u * 36u);
  for (auto [threads, chunk] : {std::pair{2, std::size_t(0)}, {5, std::size_t(3)}, {8, std::size_t(100)}}) {
    const Drawn d = draw("uniform", 7.0f, threads, chunk);
    EXPECT_EQ(d.color, one.color) << threads << " threads, chunk " << chunk;
    EXPECT_EQ(d.depth, one.depth);
    EXPECT_TRUE(same_records(d.surface, one.surface));
  }
}

TEST(UniformTessellator, AgreesWithThePrimitiveGeneratorAtLevelOne) {
  const Drawn tpg = draw("primitive_generator", 1.0f), uni = draw("uniform", 1.0f);
  EXPECT_EQ(uni.surface.triangle_count(), 256u);
  EXPECT_TRUE(same_records(uni.surface, tpg.surface));
  EXPECT_EQ(uni.color, tpg.color);
  EXPECT_EQ(uni.depth, tpg.depth);
  EXPECT_EQ(relative_hausdorff(tpg.surface, uni.surface), 0.0);
}

TEST(UniformTessellator, DiffersFromThePrimitiveGeneratorAboveLevelOne) {
  // Same levels, different patterns: the cache must not hand one tessellator's pattern to the other.
  const Drawn tpg = draw("primitive_generator", 5.0f), uni = draw("uniform", 5.0f);
  EXPECT_EQ(tpg.surface.triangle_count(), 256u * 37u);  // the TPG's rings at level 5
  EXPECT_EQ(uni.surface.triangle_count(), 256u * 25u);
  EXPECT_NE(uni.color, tpg.color);
}

TEST(UniformTessellator, HausdorffDistanceShrinksAsTheLevelGrows) {
  // Measured (docs/uniform-subdivision.md, 1024 px run: the surfaces do not depend on the image),
  // relative to the bounding-box diagonal; 2% tolerance for a change of evaluation order.
  const struct {
    float level;
    double hausdorff;
  } expected[] = {{2.0f, 5.1929e-3}, {3.0f, 1.3071e-3}, {5.0f, 6.2616e-4},
                  {8.0f, 2.7847e-4}, {13.0f, 1.1242e-4}, {21.0f, 4.5937e-5}};
  double previous = 1.0;
  for (const auto& e : expected) {
    const double h = relative_hausdorff(draw("primitive_generator", e.level).surface, draw("uniform", e.level).surface);
    EXPECT_NEAR(h, e.hausdorff, 0.02 * e.hausdorff) << "level " << e.level;
    EXPECT_LT(h, previous) << "level " << e.level;
    previous = h;
  }
}

TEST(UniformTessellator, SceneKeysRefuseWhatIsNotPlumbed) {
  auto message = [](const std::vector<std::string>& sets) {
    try {
      load_scene("", sets);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({"tessellation.tessellator=uniform", "tessellation.adaptive.enabled=true"})
                .find("tessellation.tessellator: \"uniform\" needs fixed levels"),
            std::string::npos);
  EXPECT_NE(message({"tessellation.tessellator=uniform", "shaders.program=twins"})
                .find("tessellation.tessellator: \"uniform\" works with shaders.program \"builtin\" only"),
            std::string::npos);
  EXPECT_NE(message({"tessellation.tessellator=grid"})
                .find("tessellation.tessellator: expected one of primitive_generator, uniform, refinement_pattern, got \"grid\""),
            std::string::npos);
  EXPECT_EQ(load_scene("", {}).tessellation.tessellator, Tessellator::PrimitiveGenerator);
}

}  // namespace
}  // namespace tessref
