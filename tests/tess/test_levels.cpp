// Constant and screen-space adaptive tessellation levels.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "stages/tess_levels_adaptive.h"
#include "tess_test_util.h"

namespace tessref {
namespace {

using test::bits;
using test::Lcg;

AdaptiveLevelSettings camera() {
  AdaptiveLevelSettings s;
  const glm::mat4 proj = glm::perspective(0.9f, 4.0f / 3.0f, 0.1f, 100.0f);
  const glm::mat4 view = glm::lookAt(glm::vec3(0.3f, 0.4f, 3.0f), glm::vec3(0), glm::vec3(0, 1, 0));
  s.view_proj = proj * view;
  s.viewport_pixels = {640, 480};
  s.pixels_per_segment = 7.0f;
  return s;
}

TEST(AdaptiveLevels, EdgeLevelIsSymmetricToTheBit) {
  const AdaptiveLevelSettings s = camera();
  Lcg rng(11);
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 a = rng.vec(-1.5f, 1.5f), b = rng.vec(-1.5f, 1.5f);
    EXPECT_EQ(bits(adaptive_edge_level(a, b, s)), bits(adaptive_edge_level(b, a, s)));
  }
}

TEST(AdaptiveLevels, SharedEdgeAgreesInBothPatches) {
  TessLevelSettings ls;
  ls.adaptive = true;
  ls.screen = camera();
  Lcg rng(12);
  for (int i = 0; i < 500; ++i) {
    const glm::vec3 A = rng.vec(-1, 1), B = rng.vec(-1, 1), C = rng.vec(-1, 1), D = rng.vec(-1, 1);
    // Edge A-B is the w = 0 edge (outer[2]) of (A, B, C); in (B, A, D) too but reversed; in
    // (D, B, A) it is the u = 0 edge (outer[0]); in (A, D, B) the v = 0 edge (outer[1]).
    const TessLevels l0 = triangle_levels(ls, A, B, C);
    const TessLevels l1 = triangle_levels(ls, B, A, D);
    const TessLevels l2 = triangle_levels(ls, D, B, A);
    const TessLevels l3 = triangle_levels(ls, A, D, B);
    EXPECT_EQ(bits(l0.outer[2]), bits(l1.outer[2]));
    EXPECT_EQ(bits(l0.outer[2]), bits(l2.outer[0]));
    EXPECT_EQ(bits(l0.outer[2]), bits(l3.outer[1]));
  }
}

TEST(AdaptiveLevels, FollowsProjectedLengthAndClamps) {
  AdaptiveLevelSettings s;  // identity view_proj: clip = world, 512 x 512 viewport
  s.pixels_per_segment = 8.0f;
  // NDC length 0.5 -> 128 pixels -> 16 segments.
  EXPECT_FLOAT_EQ(adaptive_edge_level({0, 0, 0}, {0.5f, 0, 0}, s), 16.0f);
  EXPECT_EQ(adaptive_edge_level({0, 0, 0}, {0, 0, 0}, s), 1.0f);       // clamped up
  EXPECT_EQ(adaptive_edge_level({-1, 0, 0}, {100, 0, 0}, s), 64.0f);   // clamped down
  EXPECT_TRUE(std::isnan(adaptive_edge_level({std::nanf(""), 0, 0}, {1, 0, 0}, s)));
  // Behind the eye (w <= 0) there is no projected length: finest level.
  AdaptiveLevelSettings c = camera();
  EXPECT_EQ(adaptive_edge_level({0, 0, 5}, {0, 0, 4}, c), c.max_level);
}

TEST(AdaptiveLevels, InnerRules) {
  TessLevelSettings ls;
  ls.adaptive = true;
  ls.screen.pixels_per_segment = 8.0f;
  const glm::vec3 a(0, 0, 0), b(0.5f, 0, 0), c(0, 0.25f, 0);  // 16, ~17.9, 8 segments
  const TessLevels mx = triangle_levels(ls, a, b, c);
  EXPECT_EQ(mx.inner[0], std::max({mx.outer[0], mx.outer[1], mx.outer[2]}));
  ls.screen.inner_rule = InnerLevelRule::Mean;
  const TessLevels mean = triangle_levels(ls, a, b, c);
  EXPECT_FLOAT_EQ(mean.inner[0], (mean.outer[0] + mean.outer[1] + mean.outer[2]) / 3.0f);
  EXPECT_FLOAT_EQ(mx.outer[2], 16.0f);
  EXPECT_FLOAT_EQ(mx.outer[1], 8.0f);
}

TEST(AdaptiveLevels, ConstantMode) {
  TessLevelSettings ls = TessLevelSettings::uniform(3.5f, 2.25f);
  TessLevels l = triangle_levels(ls, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  for (int i = 0; i < 4; ++i) EXPECT_EQ(l.outer[i], 3.5f);
  EXPECT_EQ(l.inner[0], 2.25f);
  EXPECT_EQ(l.inner[1], 2.25f);
  // Per-edge constant levels are written as given (NaN included: the generator decides).
  ls.constant.outer = {1.5f, 2.5f, std::nanf(""), 7.0f};
  l = triangle_levels(ls, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  EXPECT_EQ(l.outer[1], 2.5f);
  EXPECT_TRUE(std::isnan(l.outer[2]));
}

TEST(AdaptiveLevels, NeighbouringPnPatchesWriteEqualLevels) {
  // The same through the control program, as the executor runs it.
  PnTcs tcs;
  tcs.levels.adaptive = true;
  tcs.levels.screen = camera();
  Lcg rng(13);
  const glm::vec3 A = rng.vec(-1, 1), B = rng.vec(-1, 1), C = rng.vec(-1, 1), D = rng.vec(-1, 1);
  const auto n = glm::vec3(0, 0, 1);
  const PatchOutput p0 = test::run_tcs(tcs, test::make_patch({test::vertex(A, n), test::vertex(B, n), test::vertex(C, n)}));
  const PatchOutput p1 = test::run_tcs(tcs, test::make_patch({test::vertex(D, n), test::vertex(B, n), test::vertex(A, n)}));
  EXPECT_EQ(bits(p0.levels.outer[2]), bits(p1.levels.outer[0]));
}

}  // namespace
}  // namespace tessref
