// Watertightness: two patches sharing an edge with the same level for it produce bitwise-identical
// points along that edge (the parameter mirrored, as the neighbour walks the edge the other way),
// for every spacing; and the profile choice for odd levels just above one, both readings.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "stages/tpg.h"
#include "stages/tpg_stream.h"

namespace tessref {
namespace {

using Vec = glm::vec3;

// World positions of a triangle patch's domain points on its edge opposite corner `opposite`
// (the edge where gl_TessCoord[opposite] == 0): pos = x*C0 + y*C1 + z*C2, as a TES would write it.
std::vector<std::array<float, 3>> shared_edge_positions(const TessDomainPoints& p,
                                                        const Vec corners[3], int opposite) {
  std::vector<std::array<float, 3>> out;
  for (const Vec& c : p.coords) {
    if (c[opposite] != 0.0f) continue;
    const Vec pos = c.x * corners[0] + c.y * corners[1] + c.z * corners[2];
    out.push_back({pos.x, pos.y, pos.z});
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(TpgWatertight, NeighbouringTrianglesShareEdgePointsBitForBit) {
  std::mt19937 rng(77);
  std::uniform_real_distribution<float> level(0.6f, 66.0f), coord(-10.0f, 10.0f);
  for (TessSpacing spacing :
       {TessSpacing::Equal, TessSpacing::FractionalOdd, TessSpacing::FractionalEven}) {
    const TessLayout layout{TessDomain::Triangles, spacing, TessWinding::Ccw, false};
    for (int n = 0; n < 3000; ++n) {
      // Patch A = (P0, P1, P2), patch B = (P2, P1, P3) share the edge P1-P2: in A it lies
      // opposite corner 0 (outer[0]), in B opposite corner 2 (outer[2]).
      const Vec p0(coord(rng), coord(rng), coord(rng)), p1(coord(rng), coord(rng), coord(rng)),
          p2(coord(rng), coord(rng), coord(rng)), p3(coord(rng), coord(rng), coord(rng));
      const Vec a_corners[3] = {p0, p1, p2}, b_corners[3] = {p2, p1, p3};
      TessLevels a, b;
      a.outer = {level(rng), level(rng), level(rng), 0.0f};
      b.outer = {level(rng), level(rng), a.outer[0], 0.0f};
      // Inner levels >= 2 keep the inner ring off the boundary (an odd inner level just above 1
      // may put inner points on the edge itself, as the spec allows).
      a.inner[0] = std::uniform_real_distribution<float>(2.0f, 66.0f)(rng);
      b.inner[0] = std::uniform_real_distribution<float>(2.0f, 66.0f)(rng);
      const auto ea = shared_edge_positions(generate_tessellation(layout, a), a_corners, 0);
      const auto eb = shared_edge_positions(generate_tessellation(layout, b), b_corners, 2);
      ASSERT_EQ(ea, eb) << to_string(spacing) << " level " << a.outer[0];
      ASSERT_GE(ea.size(), 2u);
    }
  }
}

TEST(TpgWatertight, TriangleAndQuadEdgesAgree) {
  // The same level on a quad edge and a triangle edge gives the same parameters: meshes mixing
  // both domains stay closed.
  std::mt19937 rng(78);
  std::uniform_real_distribution<float> level(0.6f, 66.0f);
  for (TessSpacing spacing :
       {TessSpacing::Equal, TessSpacing::FractionalOdd, TessSpacing::FractionalEven}) {
    for (int n = 0; n < 2000; ++n) {
      const float shared = level(rng);
      TessLevels t, q;
      t.outer = {shared, level(rng), level(rng), 0.0f};
      t.inner[0] = 3.5f;
      q.outer = {shared, level(rng), level(rng), level(rng)};
      q.inner = {3.5f, 2.5f};
      std::vector<float> tp, qp;
      for (const Vec& c :
           generate_tessellation({TessDomain::Triangles, spacing, TessWinding::Ccw, false}, t).coords)
        if (c.x == 0.0f) tp.push_back(c.y);  // edge u = 0, parameter v
      for (const Vec& c :
           generate_tessellation({TessDomain::Quads, spacing, TessWinding::Ccw, false}, q).coords)
        if (c.x == 0.0f) qp.push_back(c.y);  // edge u = 0, parameter v
      std::sort(tp.begin(), tp.end());
      std::sort(qp.begin(), qp.end());
      ASSERT_EQ(tp, qp) << to_string(spacing) << " level " << shared;
    }
  }
}

// llvmpipe rounds levels to 16.16 first, so fractional_odd levels in (1, 1 + 2^-17] act as 1 and
// an all-such patch is one triangle. The literal GL text rounds any level above 1 up to 3.
TEST(TpgProfile, OddLevelJustAboveOne) {
  const TessLayout layout{TessDomain::Triangles, TessSpacing::FractionalOdd, TessWinding::Ccw,
                          false};
  TessLevels l;
  l.outer = {1.0000001f, 1.0000001f, 1.0000001f, 0.0f};
  l.inner = {1.0f, 1.0f};
  const TessDomainPoints llvmpipe = generate_tessellation(layout, l, TessProfile::llvmpipe());
  EXPECT_EQ(llvmpipe.primitive_count(), 1u);
  EXPECT_EQ(llvmpipe.coords.size(), 3u);

  const TessDomainPoints literal = generate_tessellation(layout, l, TessProfile::spec_literal());
  // Three segments on each outer edge (4 points each, 9 on the ring) around a degenerate inner
  // ring; every coordinate still in [0, 1].
  int on_u0 = 0;
  for (const Vec& c : literal.coords) on_u0 += c.x == 0.0f;
  EXPECT_GE(on_u0, 4);
  EXPECT_GT(literal.primitive_count(), 1u);
  // Just past the collapse threshold both readings agree again.
  l.outer = {1.0001f, 1.0001f, 1.0001f, 0.0f};
  EXPECT_EQ(emitted_stream(generate_tessellation(layout, l, TessProfile::llvmpipe())),
            emitted_stream(generate_tessellation(layout, l, TessProfile::spec_literal())));
}

TEST(TpgKnownValues, MeasuredOnLlvmpipe) {
  // fractional_odd, all levels 4: 37 triangles, with 0.733337402 (= 48060 / 65536) among the
  // coordinates (measured on Mesa 22.3.6).
  TessLevels l;
  l.outer = {4, 4, 4, 0};
  l.inner = {4, 0};
  const auto p = generate_tessellation(
      {TessDomain::Triangles, TessSpacing::FractionalOdd, TessWinding::Ccw, false}, l);
  EXPECT_EQ(p.primitive_count(), 37u);
  bool found = false;
  for (const Vec& c : p.coords) found |= c.x == 48060.0f / 65536.0f;
  EXPECT_TRUE(found);
  // Equal spacing, all ones: one triangle, corners in the order v = 1, w = 1, u = 1.
  TessLevels ones;
  const auto one = emitted_stream(generate_tessellation({}, ones));
  ASSERT_EQ(one.size(), 3u);
  EXPECT_EQ(one[0], Vec(0, 1, 0));
  EXPECT_EQ(one[1], Vec(0, 0, 1));
  EXPECT_EQ(one[2], Vec(1, 0, 0));
}

}  // namespace
}  // namespace tessref
