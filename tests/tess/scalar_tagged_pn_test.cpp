// Scalar Tagged PN triangles (stages/schemes/scalar_tagged_pn.h): neutral tags give PnTcs's net
// bit for bit; tension pulls the tangent coefficients towards their vertex; sharpness with a
// crease vector opens a crease (measured: the angle between the two patches across the crease
// edge, and between their shading normals) while the crease edge stays watertight; bias moves a
// bent crease curve sideways.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>

#include "stages/schemes/scalar_tagged_pn.h"
#include "tess_test_util.h"

namespace tessref {
namespace {

using namespace test;  // tess_test_util.h

StageVertex tagged(const glm::vec3& p, const glm::vec3& n, const VertexTags& t = {}) {
  StageVertex v = vertex(p, n);
  v.attr[kAttrTags] = glm::vec4(t.tension, t.sharpness, t.bias, 0.0f);
  v.attr[kAttrCrease] = glm::vec4(t.crease, 0.0f);
  return v;
}

PatchOutput stpn_net(const std::vector<StageVertex>& vs, PnNormalMode mode = PnNormalMode::Quadratic) {
  ScalarTaggedPnTcs tcs;
  tcs.pn.normal_mode = mode;
  return run_tcs(tcs, make_patch(vs));
}

double angle(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

TEST(ScalarTaggedPn, NeutralTagsGivePnsNetBitForBit) {
  Lcg rng(21);
  for (int mode = 0; mode < 4; ++mode)
    for (int trial = 0; trial < 200; ++trial) {
      std::vector<StageVertex> vs;
      for (int c = 0; c < 3; ++c) vs.push_back(tagged(rng.vec(-2, 2), rng.vec(-1, 1)));
      PnTcs pn;
      pn.normal_mode = PnNormalMode(mode);
      const PatchOutput a = run_tcs(pn, make_patch(vs)), b = stpn_net(vs, PnNormalMode(mode));
      for (int c = 0; c < 3; ++c)
        for (int s = 0; s <= kPnAttrMidNormal; ++s)
          ASSERT_EQ(std::memcmp(&a.vertices[c].attr[s], &b.vertices[c].attr[s], sizeof(glm::vec4)), 0)
              << "mode " << mode << " corner " << c << " slot " << s;
      ASSERT_EQ(std::memcmp(&a.patch[kPnPatchCenter], &b.patch[kPnPatchCenter], sizeof(glm::vec4)), 0);
      ASSERT_EQ(std::memcmp(&a.patch[kPnPatchOrder], &b.patch[kPnPatchOrder], sizeof(glm::vec4)), 0);
      PnTes tes;
      tes.normal_mode = PnNormalMode(mode);
      const glm::vec3 tc(0.2f, 0.3f, 0.5f);
      const ClipVertex x = tes.evaluate(tc, a, 0), y = tes.evaluate(tc, b, 0);
      ASSERT_EQ(std::memcmp(&x, &y, sizeof x), 0);
    }
}

TEST(ScalarTaggedPn, TensionPullsTheCoefficientsTowardsTheVertex) {
  // A curved patch: normals tilted outwards. Tension 1 puts both coefficients of vertex 0 on P0;
  // the edge curve's bulge at its middle shrinks as the tension grows.
  const glm::vec3 p0(0, 0, 0), p1(1, 0, 0), p2(0, 1, 0);
  const glm::vec3 n0 = glm::normalize(glm::vec3(-0.4f, -0.4f, 1)), n1 = glm::normalize(glm::vec3(0.5f, 0, 1)),
                  n2 = glm::normalize(glm::vec3(0, 0.5f, 1));
  double previous = 1e9;
  for (float theta : {-0.5f, 0.0f, 0.5f, 1.0f}) {
    VertexTags t;
    t.tension = theta;
    const PatchOutput net = stpn_net({tagged(p0, n0, t), tagged(p1, n1, t), tagged(p2, n2, t)});
    if (theta == 1.0f) {
      EXPECT_EQ(glm::vec3(net.vertices[0].attr[kPnAttrTangentNext]), p0);
      EXPECT_EQ(glm::vec3(net.vertices[0].attr[kPnAttrTangentPrev]), p0);
    }
    const double bulge = std::fabs(pn_position(net, {0.5f, 0.5f, 0.0f}).z);
    std::printf("[ figures  ] tension %+.1f: edge bulge at its middle %.5f\n", theta, bulge);
    EXPECT_LT(bulge, previous) << theta;
    previous = bulge;
  }
  EXPECT_LT(previous, 1e-6);  // tension 1 everywhere: the straight edge
}

// A roof: the crease edge A-B along x, the smooth normals up, the crease vector across (+y).
// Triangle "up" (A, B, C) lies on the +y side, "down" (B, A, D) on the -y side.
struct Roof {
  glm::vec3 a{0, 0, 0}, b{1, 0, 0}, c{0.5f, 0.8f, -0.3f}, d{0.5f, -0.8f, -0.3f};
  glm::vec3 up = glm::vec3(0, 0, 1);
  glm::vec3 nc = glm::normalize(glm::vec3(0, 0.6f, 1)), nd = glm::normalize(glm::vec3(0, -0.6f, 1));
  PatchOutput one, two;
  Roof(float sharpness, float bias = 0.0f, glm::vec3 na = glm::vec3(0, 0, 1), glm::vec3 nb = glm::vec3(0, 0, 1),
       PnNormalMode mode = PnNormalMode::Quadratic) {
    VertexTags t;
    t.sharpness = sharpness;
    t.bias = bias;
    t.crease = glm::vec3(0, 1, 0);
    one = stpn_net({tagged(a, na, t), tagged(b, nb, t), tagged(c, nc)}, mode);
    two = stpn_net({tagged(b, nb, t), tagged(a, na, t), tagged(d, nd)}, mode);
  }
  // The geometric normal of each patch at the crease edge's point t (A at 0).
  double dihedral(float t) const {
    glm::vec3 u1, v1, u2, v2;
    pn_derivatives(one, {1 - t, t, 0}, u1, v1);
    pn_derivatives(two, {t, 1 - t, 0}, u2, v2);
    const glm::dvec3 m1 = glm::cross(glm::dvec3(u1), glm::dvec3(v1)), m2 = glm::cross(glm::dvec3(u2), glm::dvec3(v2));
    // Both patches run counter-clockwise seen from above: their normals point up.
    return angle(m1, m2);
  }
};

TEST(ScalarTaggedPn, SharpnessOpensACreaseThatStaysWatertight) {
  double previous = -1.0;
  for (float sigma : {0.0f, 0.5f, 1.0f}) {
    const Roof r(sigma);
    const double geometric = r.dihedral(0.5f) * 180.0 / M_PI;
    const double shading = angle(glm::dvec3(glm::vec3(r.one.vertices[0].attr[kAttrNormal])),
                                 glm::dvec3(glm::vec3(r.two.vertices[1].attr[kAttrNormal]))) * 180.0 / M_PI;
    std::printf("[ figures  ] sharpness %.1f: angle across the crease at its middle %.2f deg, corner "
                "shading normals %.2f deg apart\n", sigma, geometric, shading);
    // Shading: N' = normalize(N +- sigma Delta) on either side, 2 atan(sigma) apart.
    EXPECT_NEAR(shading, 2.0 * std::atan(sigma) * 180.0 / M_PI, 1e-3);
    EXPECT_GT(geometric, previous + 5.0);
    previous = geometric;
    // The crease edge: the same points and, the shading aside, from both patches.
    for (int i = 0; i <= 16; ++i) {
      const float t = float(i) / 16.0f;
      EXPECT_TRUE(same_bits(pn_position(r.one, {1 - t, t, 0}), pn_position(r.two, {t, 1 - t, 0}))) << sigma << " " << t;
    }
  }
  EXPECT_GT(previous, 30.0);
}

TEST(ScalarTaggedPn, BiasMovesABentCreaseSideways) {
  // The crease bends down at both ends (normals tilted along the edge): the crease curve leaves
  // the x axis only through Y = normalize(N + bias Delta).
  const glm::vec3 na = glm::normalize(glm::vec3(-0.5f, 0, 1)), nb = glm::normalize(glm::vec3(0.5f, 0, 1));
  auto sideways = [&](float beta) { return pn_position(Roof(1.0f, beta, na, nb).one, {0.5f, 0.5f, 0.0f}).y; };
  const float zero = sideways(0.0f), plus = sideways(0.5f), minus = sideways(-0.5f), full = sideways(1.0f);
  std::printf("[ figures  ] crease middle off the axis: bias 0 %.5f, 0.5 %.5f, -0.5 %.5f, 1 %.5f\n", zero, plus,
              minus, full);
  EXPECT_EQ(zero, 0.0f);
  EXPECT_NE(plus, 0.0f);
  EXPECT_NEAR(plus, -minus, 1e-6f);
  EXPECT_GT(std::fabs(full), std::fabs(plus));
  // Both patches still share the crease.
  const Roof r(1.0f, 0.5f, na, nb);
  for (int i = 0; i <= 8; ++i) {
    const float t = float(i) / 8.0f;
    EXPECT_TRUE(same_bits(pn_position(r.one, {1 - t, t, 0}), pn_position(r.two, {t, 1 - t, 0})));
  }
}

TEST(ScalarTaggedPn, WorldCreaseKeepsItsLength) {
  const glm::mat3 m(2.0f, 0.0f, 0.0f, 0.0f, 0.5f, 0.0f, 0.0f, 0.0f, 1.0f);
  const glm::vec3 w = world_crease(m, glm::vec3(0.0f, 0.3f, 0.4f));
  EXPECT_NEAR(glm::length(w), 0.5f, 1e-6f);
  EXPECT_EQ(world_crease(m, glm::vec3(0.0f)), glm::vec3(0.0f));
}

}  // namespace
}  // namespace tessref
