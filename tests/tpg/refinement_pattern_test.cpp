// Seed 001's refinement pattern (stages/tpg_refinement.h): the level-of-detail mapping, counts,
// exact dyadic barycentric coordinates, nested patterns, the same triangles as the uniform grid of
// 2^k segments, ccw winding, a closed pattern whose edges read the same from both patches of a
// shared edge, the discard rule, and the cache keeping it apart from the other tessellators.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

#include "stages/tpg.h"
#include "stages/tpg_cache.h"
#include "stages/tpg_refinement.h"
#include "stages/tpg_uniform.h"
#include "tpg_test_util.h"

namespace tessref {
namespace {

using test::area2;
using test::levels_of;
const TessLayout& kCcw = test::kCcwTriangles;
const TessProfile kProfile = TessProfile::llvmpipe();

TessDomainPoints pattern(float level, const TessLayout& layout = kCcw) {
  TessDomainPoints out;
  generate_refinement_pattern(layout, levels_of(level), kProfile, out);
  return out;
}

TEST(RefinementPattern, LevelOfDetailFromTheLargestOuterLevel) {
  const std::pair<float, int> table[] = {{0.25f, 0}, {1.0f, 0}, {1.5f, 1}, {2.0f, 1}, {2.01f, 2}, {3.0f, 2},
                                         {4.0f, 2},  {5.0f, 3}, {8.0f, 3},  {12.0f, 4}, {13.0f, 4}, {16.0f, 4},
                                         {21.0f, 5}, {32.0f, 5}, {33.0f, 6}, {64.0f, 6}, {1e30f, 6},
                                         {std::numeric_limits<float>::infinity(), 6}};
  for (const auto& [level, lod] : table) EXPECT_EQ(refinement_lod(levels_of(level), kProfile), lod) << level;
  // One edge decides; inner levels do not count.
  TessLevels l = levels_of(1.0f, 64.0f);
  l.outer[1] = 7.0f;
  EXPECT_EQ(refinement_lod(l, kProfile), 3);
  // A smaller largest level clamps the pattern.
  TessProfile small = kProfile;
  small.max_level = 16;
  EXPECT_EQ(refinement_lod(levels_of(64.0f), small), 4);
  // The generator's discard rule.
  for (float bad : {0.0f, -1.0f, std::numeric_limits<float>::quiet_NaN()}) {
    TessLevels d = levels_of(8.0f);
    d.outer[2] = bad;
    EXPECT_EQ(refinement_lod(d, kProfile), -1) << bad;
    TessDomainPoints out;
    generate_refinement_pattern(kCcw, d, kProfile, out);
    EXPECT_TRUE(out.discarded);
    EXPECT_TRUE(out.coords.empty());
    EXPECT_TRUE(out.indices.empty());
  }
}

TEST(RefinementPattern, CountsPerLevelOfDetail) {
  const std::size_t points[] = {3, 6, 15, 45, 153, 561, 2145};
  const std::size_t triangles[] = {1, 4, 16, 64, 256, 1024, 4096};
  for (int k = 0; k <= kMaxRefinementLod; ++k) {
    const TessDomainPoints p = pattern(float(1 << k));
    EXPECT_FALSE(p.discarded);
    EXPECT_EQ(p.coords.size(), points[k]) << k;
    EXPECT_EQ(p.primitive_count(), triangles[k]) << k;
    EXPECT_EQ(refinement_point_count(k), points[k]);
    EXPECT_EQ(refinement_triangle_count(k), triangles[k]);
  }
  // Levels between powers of two take the next pattern up: 5 -> 8 segments.
  EXPECT_EQ(pattern(5.0f).primitive_count(), 64u);
}

TEST(RefinementPattern, CoordinatesAreExactDyadicBarycentrics) {
  for (int k = 0; k <= kMaxRefinementLod; ++k) {
    const int n = 1 << k;
    const TessDomainPoints p = pattern(float(n));
    std::set<std::pair<int, int>> seen;
    for (const glm::vec3& c : p.coords) {
      const float i = c.x * float(n), j = c.y * float(n), l = c.z * float(n);
      EXPECT_EQ(i, std::floor(i));
      EXPECT_EQ(j, std::floor(j));
      EXPECT_EQ(l, std::floor(l));
      // No rounding anywhere: the three sum to exactly 1, and w = 1 - u - v to the bit.
      EXPECT_EQ(c.x + c.y + c.z, 1.0f);
      EXPECT_EQ(1.0f - c.x - c.y, c.z);
      EXPECT_EQ(int(i) + int(j) + int(l), n);
      EXPECT_TRUE(seen.insert({int(i), int(j)}).second) << "a point twice, k = " << k;
    }
  }
}

TEST(RefinementPattern, PatternsAreNestedPrefixes) {
  // The corners first, in the generator's order for its single triangle.
  const TessDomainPoints rp0 = pattern(1.0f);
  ASSERT_EQ(rp0.coords.size(), 3u);
  EXPECT_EQ(rp0.coords[0], glm::vec3(0, 1, 0));
  EXPECT_EQ(rp0.coords[1], glm::vec3(0, 0, 1));
  EXPECT_EQ(rp0.coords[2], glm::vec3(1, 0, 0));
  EXPECT_EQ(rp0.indices, (std::vector<std::uint32_t>{0, 1, 2}));
  TessDomainPoints tpg;
  generate_tessellation(kCcw, levels_of(1.0f), kProfile, tpg);
  EXPECT_EQ(rp0.coords, tpg.coords);
  EXPECT_EQ(rp0.indices, tpg.indices);
  for (int k = 1; k <= kMaxRefinementLod; ++k) {
    const TessDomainPoints coarse = pattern(float(1 << (k - 1))), fine = pattern(float(1 << k));
    ASSERT_LT(coarse.coords.size(), fine.coords.size());
    EXPECT_TRUE(std::equal(coarse.coords.begin(), coarse.coords.end(), fine.coords.begin())) << k;
  }
}

// Triangles as sorted coordinate triples, each rotated to start at its smallest corner (keeps
// the winding).
std::vector<std::array<float, 9>> triangle_set(const TessDomainPoints& p) {
  std::vector<std::array<float, 9>> out;
  for (std::size_t t = 0; t < p.primitive_count(); ++t) {
    std::array<glm::vec3, 3> v;
    for (int c = 0; c < 3; ++c) v[c] = p.coords[p.indices[3 * t + c]];
    auto less = [](const glm::vec3& a, const glm::vec3& b) {
      return std::make_tuple(a.x, a.y, a.z) < std::make_tuple(b.x, b.y, b.z);
    };
    const int first = int(std::min_element(v.begin(), v.end(), less) - v.begin());
    std::array<float, 9> key;
    for (int c = 0; c < 3; ++c)
      for (int d = 0; d < 3; ++d) key[3 * c + d] = v[(first + c) % 3][d];
    out.push_back(key);
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(RefinementPattern, SameTrianglesAsTheUniformGridOfPowerOfTwoSegments) {
  for (int k = 0; k <= kMaxRefinementLod; ++k) {
    TessDomainPoints grid;
    generate_uniform(kCcw, levels_of(float(1 << k)), kProfile, grid);
    EXPECT_EQ(triangle_set(pattern(float(1 << k))), triangle_set(grid)) << k;
  }
  // ... but not at other levels: 3 -> 4 segments here, 3 on the uniform grid.
  TessDomainPoints grid3;
  generate_uniform(kCcw, levels_of(3.0f), kProfile, grid3);
  EXPECT_EQ(grid3.primitive_count(), 9u);
  EXPECT_EQ(pattern(3.0f).primitive_count(), 16u);
}

TEST(RefinementPattern, TrianglesAreCounterClockwiseOrReversedForCw) {
  TessLayout cw = kCcw;
  cw.winding = TessWinding::Cw;
  for (int k : {0, 1, 3, 6}) {
    const int n = 1 << k;
    const TessDomainPoints a = pattern(float(n)), b = pattern(float(n), cw);
    ASSERT_EQ(a.coords, b.coords);
    const double cell = 1.0 / (double(n) * n);
    for (std::size_t t = 0; t < a.primitive_count(); ++t) {
      EXPECT_EQ(area2(a, t), cell) << "k " << k << " triangle " << t;  // exact: dyadic coordinates
      EXPECT_EQ(area2(b, t), -cell);
    }
  }
}

TEST(RefinementPattern, ClosedInsideAndWatertightAcrossSharedEdges) {
  for (int k = 0; k <= kMaxRefinementLod; ++k) {
    const int n = 1 << k;
    const TessDomainPoints p = pattern(float(n));
    // Inside: every directed edge once; an interior edge also runs the other way, a boundary
    // edge (on u, v or w = 0) does not.
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (std::size_t t = 0; t < p.primitive_count(); ++t)
      for (int e = 0; e < 3; ++e) ++directed[{p.indices[3 * t + e], p.indices[3 * t + (e + 1) % 3]}];
    int boundary = 0;
    for (const auto& [edge, count] : directed) {
      EXPECT_EQ(count, 1);
      const glm::vec3 a = p.coords[edge.first], b = p.coords[edge.second];
      const bool on_side = (a.x == 0 && b.x == 0) || (a.y == 0 && b.y == 0) || (a.z == 0 && b.z == 0);
      EXPECT_EQ(directed.count({edge.second, edge.first}), on_side ? 0u : 1u);
      boundary += on_side;
    }
    EXPECT_EQ(boundary, 3 * n);
    // Across patches: the neighbour walks a shared edge the other way, so its parameter t there
    // is this patch's 1 - t. Each side's parameters are closed under t -> 1 - t, exactly.
    for (int side = 0; side < 3; ++side) {
      std::multiset<float> t, mirrored;
      for (const glm::vec3& c : p.coords)
        if (c[side] == 0.0f) {
          const float s = c[(side + 1) % 3];
          t.insert(s);
          mirrored.insert(1.0f - s);
        }
      EXPECT_EQ(t.size(), std::size_t(n + 1));
      EXPECT_EQ(t, mirrored) << "k " << k << " side " << side;
    }
  }
}

TEST(RefinementPattern, PointModeQuadsAndTheCache) {
  TessLayout points = kCcw;
  points.point_mode = true;
  const TessDomainPoints p = pattern(8.0f, points);
  EXPECT_EQ(p.coords.size(), 45u);
  EXPECT_EQ(p.indices.size(), 45u);
  EXPECT_EQ(p.vertices_per_primitive, 1);
  TessLayout quads = kCcw;
  quads.domain = TessDomain::Quads;
  TessDomainPoints out;
  EXPECT_THROW(generate_refinement_pattern(quads, levels_of(4.0f), kProfile, out), std::invalid_argument);

  TessPatternCache cache;
  const TessLevels l = levels_of(3.0f);
  const auto rp = cache.get(kCcw, l, kProfile, Tessellator::RefinementPattern);
  const auto uni = cache.get(kCcw, l, kProfile, Tessellator::Uniform);
  EXPECT_EQ(rp->points.primitive_count(), 16u);
  EXPECT_EQ(uni->points.primitive_count(), 9u);
  EXPECT_EQ(cache.get(kCcw, l, kProfile, Tessellator::RefinementPattern), rp);

  Tessellator t{};
  EXPECT_TRUE(parse("refinement_pattern", t));
  EXPECT_EQ(t, Tessellator::RefinementPattern);
  EXPECT_STREQ(to_string(Tessellator::RefinementPattern), "refinement_pattern");
}

}  // namespace
}  // namespace tessref
