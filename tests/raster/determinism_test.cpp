// The framebuffer bytes and the statistics do not depend on the thread count, and several draws
// in a row equal one draw of the concatenated batches.
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "raster_test_util.h"

namespace tessref {
namespace {

constexpr int kW = 300, kH = 200;  // not a multiple of the tile size

// A mixed batch: small and large triangles, some off screen, some crossing near or far, some
// behind the eye, a few with NaN positions; 4 random varyings each.
TriangleBatch random_batch(std::size_t count, std::uint32_t seed, float size_scale = 1.0f) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  TriangleBatch b;
  b.num_varyings = 4;
  for (std::size_t t = 0; t < count; ++t) {
    const float size =
        size_scale * std::exp(u(rng) * std::log(u(rng) < 0.05f ? 3.0f : 0.6f));  // NDC units
    const glm::vec3 c(u(rng) * 2.6f - 1.3f, u(rng) * 2.6f - 1.3f, u(rng) * 2.4f - 1.2f);
    for (int k = 0; k < 3; ++k) {
      ClipVertex v;
      const float w = u(rng) < 0.02f ? -1.0f : 0.3f + 2.0f * u(rng);
      const glm::vec3 p =
          c + size * glm::vec3(u(rng) - 0.5f, u(rng) - 0.5f, 0.3f * (u(rng) - 0.5f));
      v.position = glm::vec4(p * w, w);
      if (u(rng) < 0.002f) v.position.x = std::numeric_limits<float>::quiet_NaN();
      for (int j = 0; j < 4; ++j) v.varyings[j] = u(rng);
      b.vertices.push_back(v);
    }
  }
  return b;
}

struct Result {
  Framebuffer fb{kW, kH, glm::vec4(0.1f, 0.2f, 0.3f, 1.0f)};
  RasterStats stats;
};

Result render(const TriangleBatch& b, int threads, bool cull) {
  Result r;
  RasterState state;
  state.cull_back_faces = cull;
  test::VaryingProgram prog;
  r.stats = draw_triangles(b, state, prog, r.fb, Parallel(threads));
  return r;
}

void expect_identical(const Result& a, const Result& b, const char* what) {
  ASSERT_EQ(a.fb.color.size(), b.fb.color.size());
  EXPECT_EQ(
      std::memcmp(a.fb.color.data(), b.fb.color.data(), a.fb.color.size() * sizeof(glm::vec4)), 0)
      << what;
  EXPECT_EQ(std::memcmp(a.fb.depth.data(), b.fb.depth.data(), a.fb.depth.size() * sizeof(float)), 0)
      << what;
  EXPECT_EQ(std::memcmp(a.fb.aux.data(), b.fb.aux.data(), a.fb.aux.size() * sizeof(glm::vec4)), 0)
      << what;
  EXPECT_EQ(a.stats.triangles_in, b.stats.triangles_in) << what;
  EXPECT_EQ(a.stats.triangles_clipped_away, b.stats.triangles_clipped_away) << what;
  EXPECT_EQ(a.stats.triangles_culled, b.stats.triangles_culled) << what;
  EXPECT_EQ(a.stats.triangles_rasterized, b.stats.triangles_rasterized) << what;
  EXPECT_EQ(a.stats.fragments_shaded, b.stats.fragments_shaded) << what;
}

TEST(RasterDeterminism, ThreadCountDoesNotChangeTheResult) {
  for (bool cull : {false, true}) {
    const TriangleBatch b = random_batch(20000, cull ? 5u : 6u);
    const Result one = render(b, 1, cull);
    // The batch exercises every path.
    EXPECT_EQ(one.stats.triangles_in, 20000u);
    EXPECT_GT(one.stats.triangles_clipped_away, 100u);
    if (cull) {
      EXPECT_GT(one.stats.triangles_culled, 5000u);
    }
    EXPECT_GT(one.stats.triangles_rasterized, 5000u);
    EXPECT_GT(one.stats.fragments_shaded, std::uint64_t(kW) * kH);
    expect_identical(one, render(b, 2, cull), "2 threads");
    expect_identical(one, render(b, 8, cull), "8 threads");
  }
}

TEST(RasterDeterminism, LargeBatchOverSeveralPasses) {
  // More triangles than one setup pass holds (64 Ki), so passes and chunks both split it.
  const TriangleBatch b = random_batch(300000, 9u, 0.1f);
  const Result one = render(b, 1, false);
  EXPECT_EQ(one.stats.triangles_in, 300000u);
  expect_identical(one, render(b, 2, false), "2 threads");
  expect_identical(one, render(b, 8, false), "8 threads");
}

TEST(RasterDeterminism, SeveralDrawsEqualOneConcatenatedDraw) {
  const TriangleBatch a = random_batch(7000, 21u), c = random_batch(5000, 22u);
  TriangleBatch both = a;
  both.vertices.insert(both.vertices.end(), c.vertices.begin(), c.vertices.end());
  const Result whole = render(both, 2, false);
  Result split;
  test::VaryingProgram prog;
  split.stats = draw_triangles(a, RasterState{}, prog, split.fb, Parallel(2));
  split.stats += draw_triangles(c, RasterState{}, prog, split.fb, Parallel(8));
  expect_identical(whole, split, "split draw");
}

}  // namespace
}  // namespace tessref
