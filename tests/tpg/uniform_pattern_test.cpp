// Uniform subdivision (stages/tpg_uniform.h): counts, the exact barycentric grid, ccw triangles,
// a closed mesh inside the patch and mirrored edge parameters across patches, n from the levels,
// the TPG's discard rule, and the pattern cache keeping the two tessellators apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <utility>

#include "stages/tpg.h"
#include "stages/tpg_cache.h"
#include "stages/tpg_uniform.h"
#include "tpg_test_util.h"

namespace tessref {
namespace {

using test::area2;
using test::levels_of;
const TessLayout& kCcw = test::kCcwTriangles;
const TessProfile kProfile = TessProfile::llvmpipe();

TessDomainPoints uniform(float level, const TessLayout& layout = kCcw) {
  TessDomainPoints out;
  generate_uniform(layout, levels_of(level), kProfile, out);
  return out;
}

TEST(UniformPattern, CountsForEveryN) {
  for (int n = 1; n <= 64; ++n) {
    const TessDomainPoints p = uniform(float(n));
    EXPECT_FALSE(p.discarded);
    EXPECT_EQ(p.coords.size(), std::size_t((n + 1) * (n + 2) / 2)) << n;
    EXPECT_EQ(p.primitive_count(), std::size_t(n * n)) << n;
    EXPECT_EQ(p.coords.size(), uniform_point_count(n));
    EXPECT_EQ(p.primitive_count(), uniform_triangle_count(n));
  }
}

TEST(UniformPattern, PointsLieOnTheExactBarycentricGridOnce) {
  for (int n : {1, 2, 3, 7, 12, 13, 64}) {
    const TessDomainPoints p = uniform(float(n));
    std::set<std::pair<int, int>> seen;
    for (const glm::vec3& c : p.coords) {
      // Each coordinate is the float nearest i / n for an integer i, and the three sum to n.
      const int i = int(std::lround(c.x * n)), j = int(std::lround(c.y * n)), k = int(std::lround(c.z * n));
      EXPECT_EQ(c.x, float(i) / float(n));
      EXPECT_EQ(c.y, float(j) / float(n));
      EXPECT_EQ(c.z, float(k) / float(n));
      EXPECT_EQ(i + j + k, n);
      EXPECT_TRUE(seen.insert({i, j}).second) << "point (" << i << ", " << j << ") twice, n = " << n;
    }
  }
}

TEST(UniformPattern, TrianglesAreCounterClockwiseOrReversedForCw) {
  TessLayout cw = kCcw;
  cw.winding = TessWinding::Cw;
  for (int n : {1, 2, 5, 21, 64}) {
    const TessDomainPoints a = uniform(float(n)), b = uniform(float(n), cw);
    ASSERT_EQ(a.coords, b.coords);
    const double cell = 1.0 / (double(n) * n);  // every sub-triangle has the same area
    for (std::size_t t = 0; t < a.primitive_count(); ++t) {
      EXPECT_NEAR(area2(a, t), cell, 1e-6) << "n " << n << " triangle " << t;
      EXPECT_NEAR(area2(b, t), -cell, 1e-6);
      EXPECT_EQ(a.indices[3 * t], b.indices[3 * t]);
      EXPECT_EQ(a.indices[3 * t + 1], b.indices[3 * t + 2]);
    }
  }
}

TEST(UniformPattern, LevelOneIsTheTpgSingleTriangle) {
  for (TessSpacing spacing : {TessSpacing::Equal, TessSpacing::FractionalOdd})
    for (TessWinding winding : {TessWinding::Ccw, TessWinding::Cw}) {
      const TessLayout layout{TessDomain::Triangles, spacing, winding, false};
      const TessDomainPoints tpg = generate_tessellation(layout, levels_of(1.0f));
      const TessDomainPoints uni = uniform(1.0f, layout);
      EXPECT_EQ(uni.coords, tpg.coords);
      EXPECT_EQ(uni.indices, tpg.indices);
    }
}

TEST(UniformPattern, InteriorEdgesAreSharedByTwoTrianglesBoundaryEdgesByOne) {
  // Sub-triangles index shared points, so the patch is a closed fan of n^2 triangles: each
  // interior edge is used once in each direction, each of the 3n boundary edges once.
  for (int n : {1, 2, 4, 9, 64}) {
    const TessDomainPoints p = uniform(float(n));
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (std::size_t t = 0; t < p.primitive_count(); ++t)
      for (int e = 0; e < 3; ++e) ++directed[{p.indices[3 * t + e], p.indices[3 * t + (e + 1) % 3]}];
    int boundary = 0;
    for (const auto& [edge, count] : directed) {
      EXPECT_EQ(count, 1);
      if (!directed.count({edge.second, edge.first})) {
        ++boundary;
        const glm::vec3 a = p.coords[edge.first], b = p.coords[edge.second];
        EXPECT_TRUE((a.x == 0 && b.x == 0) || (a.y == 0 && b.y == 0) || (a.z == 0 && b.z == 0));
      }
    }
    EXPECT_EQ(boundary, 3 * n);
  }
}

TEST(UniformPattern, NeighbouringPatchesShareEdgePointsBitForBit) {
  // Patch A = (P0, P1, P2) and B = (P2, P1, P3) share P1-P2: in A opposite corner 0, in B opposite
  // corner 2, walked the other way. The same n gives the same positions along it.
  const glm::vec3 p0(0.3f, -1.7f, 2.1f), p1(1.1f, 0.2f, -0.7f), p2(-2.3f, 0.9f, 0.4f), p3(0.5f, 3.1f, 1.9f);
  auto edge = [](const TessDomainPoints& p, const glm::vec3 (&corner)[3], int opposite) {
    std::vector<std::array<float, 3>> out;
    for (const glm::vec3& c : p.coords)
      if (c[opposite] == 0.0f) {
        const glm::vec3 pos = c.x * corner[0] + c.y * corner[1] + c.z * corner[2];
        out.push_back({pos.x, pos.y, pos.z});
      }
    std::sort(out.begin(), out.end());
    return out;
  };
  const glm::vec3 a[3] = {p0, p1, p2}, b[3] = {p2, p1, p3};
  for (int n = 1; n <= 64; ++n) {
    const TessDomainPoints p = uniform(float(n));
    const auto ea = edge(p, a, 0), eb = edge(p, b, 2);
    ASSERT_EQ(ea.size(), std::size_t(n + 1));
    ASSERT_EQ(ea, eb) << "n = " << n;
  }
}

TEST(UniformPattern, SegmentsFromLevels) {
  // n = the largest outer level rounded up, clamped to [1, max_level]; inner levels do not count.
  EXPECT_EQ(uniform_segments(levels_of(1.0f), kProfile), 1);
  EXPECT_EQ(uniform_segments(levels_of(0.25f), kProfile), 1);
  EXPECT_EQ(uniform_segments(levels_of(1.0001f), kProfile), 2);
  EXPECT_EQ(uniform_segments(levels_of(12.0f), kProfile), 12);
  EXPECT_EQ(uniform_segments(levels_of(12.5f), kProfile), 13);
  EXPECT_EQ(uniform_segments(levels_of(64.0f), kProfile), 64);
  EXPECT_EQ(uniform_segments(levels_of(65.0f), kProfile), 64);
  EXPECT_EQ(uniform_segments(levels_of(1e30f), kProfile), 64);
  EXPECT_EQ(uniform_segments(levels_of(std::numeric_limits<float>::infinity()), kProfile), 64);
  EXPECT_EQ(uniform_segments(levels_of(3.0f, 40.0f), kProfile), 3);
  TessLevels mixed = levels_of(2.0f);
  mixed.outer[1] = 7.5f;
  mixed.outer[3] = 50.0f;  // not used by triangles
  EXPECT_EQ(uniform_segments(mixed, kProfile), 8);
  TessProfile small = kProfile;
  small.max_level = 16;
  EXPECT_EQ(uniform_segments(levels_of(40.0f), small), 16);
}

TEST(UniformPattern, DiscardsWhatTheTpgDiscards) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (float bad : {0.0f, -0.0f, -1.0f, nan, -std::numeric_limits<float>::infinity()})
    for (int e = 0; e < 3; ++e) {
      TessLevels l = levels_of(5.0f);
      l.outer[e] = bad;
      TessDomainPoints out;
      generate_uniform(kCcw, l, kProfile, out);
      EXPECT_TRUE(out.discarded) << bad << " at outer[" << e << "]";
      EXPECT_TRUE(out.coords.empty());
      EXPECT_EQ(generate_tessellation(kCcw, l).discarded, out.discarded);
      EXPECT_EQ(uniform_segments(l, kProfile), 0);
    }
  // A NaN inner level clamps in the TPG; the uniform grid ignores it.
  TessLevels l = levels_of(4.0f);
  l.inner = {nan, nan};
  EXPECT_EQ(uniform(4.0f).coords.size(), 15u);
  TessDomainPoints out;
  generate_uniform(kCcw, l, kProfile, out);
  EXPECT_FALSE(out.discarded);
  EXPECT_EQ(out.primitive_count(), 16u);
}

TEST(UniformPattern, PointModeAndOtherDomains) {
  TessLayout points = kCcw;
  points.point_mode = true;
  const TessDomainPoints p = uniform(6.0f, points);
  EXPECT_EQ(p.vertices_per_primitive, 1);
  EXPECT_EQ(p.primitive_count(), p.coords.size());
  TessLayout quads = kCcw;
  quads.domain = TessDomain::Quads;
  TessDomainPoints out;
  EXPECT_THROW(generate_uniform(quads, levels_of(3.0f), kProfile, out), std::invalid_argument);
}

TEST(UniformPattern, CacheKeepsTheTessellatorsApart) {
  TessPatternCache cache;
  const TessLevels l = levels_of(5.0f);
  const auto tpg = cache.get(kCcw, l, kProfile);
  const auto uni = cache.get(kCcw, l, kProfile, Tessellator::Uniform);
  EXPECT_NE(tpg, uni);
  EXPECT_EQ(tpg->points.coords, generate_tessellation(kCcw, l).coords);
  EXPECT_EQ(uni->points.coords, uniform(5.0f).coords);
  EXPECT_EQ(cache.get(kCcw, l, kProfile, Tessellator::Uniform), uni);
  EXPECT_EQ(cache.get(kCcw, l, kProfile, Tessellator::PrimitiveGenerator), tpg);
  EXPECT_EQ(cache.stats().misses, 2u);
  // The padded structure-of-arrays copy the batched TES reads.
  for (std::size_t i = 0; i < uni->points.coords.size(); ++i)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(uni->coord[c][i], uni->points.coords[i][c]);
}

TEST(UniformPattern, Names) {
  Tessellator t{};
  EXPECT_TRUE(parse("uniform", t));
  EXPECT_EQ(t, Tessellator::Uniform);
  EXPECT_TRUE(parse("primitive_generator", t));
  EXPECT_EQ(t, Tessellator::PrimitiveGenerator);
  EXPECT_FALSE(parse("Uniform", t));
  EXPECT_STREQ(to_string(Tessellator::Uniform), "uniform");
}

}  // namespace
}  // namespace tessref
