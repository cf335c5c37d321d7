// stages/schemes/bezier_nets.h: the four interpolants of seed 004 in Bézier form, against their
// defining properties (corner interpolation, tangent planes, NLSA = Phong(1/2), Nagata's
// threshold) and the derivatives against finite differences.
#include "stages/schemes/bezier_nets.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tess_test_util.h"

namespace tessref {
namespace {

using namespace schemes;
using dvec3 = glm::dvec3;

constexpr Interpolant kAll[] = {Interpolant::PN, Interpolant::Phong, Interpolant::NLSA,
                                Interpolant::Nagata};

struct Triangle {
  dvec3 p[3], n[3];
};

// A triangle with its normals tilted from the face normal by up to ~50 degrees: curved patches of
// every kind, no degenerate edges.
Triangle random_triangle(test::Lcg& rng) {
  auto x = [](test::Lcg& r) { return double(r.uniform(-1.0f, 1.0f)); };
  Triangle t;
  for (;;) {
    for (auto& p : t.p) p = dvec3(x(rng), x(rng), x(rng));
    const dvec3 face = glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
    if (glm::length(face) < 0.3) continue;
    const dvec3 f = glm::normalize(face);
    for (auto& n : t.n) n = glm::normalize(f + 0.6 * dvec3(x(rng), x(rng), x(rng)));
    return t;
  }
}

std::string name(Interpolant s) { return to_string(s); }

TEST(BezierNets, IndexEnumeratesTheNet) {
  using C = CubicNet<double>;
  bool seen[10] = {};
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; i + j <= 3; ++j) {
      const int k = 3 - i - j;
      ASSERT_GE(C::index(i, j, k), 0);
      ASSERT_LT(C::index(i, j, k), 10);
      EXPECT_FALSE(seen[C::index(i, j, k)]);
      seen[C::index(i, j, k)] = true;
    }
  EXPECT_EQ(C::index(3, 0, 0), 0);
  EXPECT_EQ(C::index(0, 0, 3), 9);
  static_assert(QuadraticNet<float>::index(0, 0, 2) == 5);
}

TEST(BezierNets, EveryPatchInterpolatesItsCorners) {
  test::Lcg rng(1);
  for (int trial = 0; trial < 50; ++trial) {
    const Triangle t = random_triangle(rng);
    for (Interpolant s : kAll) {
      const CubicNet<double> net = cubic_net(s, t.p, t.n, InterpolantParams{});
      const double uv[3][2] = {{0, 0}, {1, 0}, {0, 1}};
      for (int c = 0; c < 3; ++c) {
        const dvec3 q = evaluate(net, uv[c][0], uv[c][1]).position;
        EXPECT_LT(glm::length(q - t.p[c]), 1e-14) << name(s) << " corner " << c;
      }
      // And in float, bit for bit (the corner control points are the corners).
      glm::vec3 pf[3], nf[3];
      for (int c = 0; c < 3; ++c) pf[c] = glm::vec3(t.p[c]), nf[c] = glm::vec3(t.n[c]);
      const CubicNet<float> f = cubic_net(s, pf, nf, InterpolantParams{});
      EXPECT_EQ(evaluate(f, 0.0f, 0.0f).position, pf[0]) << name(s);
      EXPECT_EQ(evaluate(f, 1.0f, 0.0f).position, pf[1]) << name(s);
      EXPECT_EQ(evaluate(f, 0.0f, 1.0f).position, pf[2]) << name(s);
    }
  }
}

// The largest |cos| between a corner normal and the patch's tangents at that corner.
double worst_tangent_cosine(const CubicNet<double>& net, const Triangle& t) {
  const double uv[3][2] = {{0, 0}, {1, 0}, {0, 1}};
  double worst = 0.0;
  for (int c = 0; c < 3; ++c) {
    const SurfacePoint<double> s = evaluate(net, uv[c][0], uv[c][1]);
    for (const dvec3& d : {s.du, s.dv})
      worst = std::max(worst, std::fabs(glm::dot(d, t.n[c])) / glm::length(d));
  }
  return worst;
}

TEST(BezierNets, PnAndNagataReproduceTheCornerTangentPlanesPhongAndNlsaDoNot) {
  test::Lcg rng(2);
  InterpolantParams params;
  params.nagata_eps = 0.0;  // the random normals are far from parallel: no edge is cut
  int phong_off = 0, nlsa_off = 0;
  const int trials = 50;
  for (int trial = 0; trial < trials; ++trial) {
    const Triangle t = random_triangle(rng);
    EXPECT_LT(worst_tangent_cosine(cubic_net(Interpolant::PN, t.p, t.n, params), t), 1e-12);
    EXPECT_LT(worst_tangent_cosine(cubic_net(Interpolant::Nagata, t.p, t.n, params), t), 1e-12);
    phong_off += worst_tangent_cosine(cubic_net(Interpolant::Phong, t.p, t.n, params), t) > 1e-3;
    nlsa_off += worst_tangent_cosine(cubic_net(Interpolant::NLSA, t.p, t.n, params), t) > 1e-3;
  }
  // Seed 004 Sec. 5: only PN and Nagata reproduce the tangent planes.
  EXPECT_EQ(phong_off, trials);
  EXPECT_EQ(nlsa_off, trials);
}

TEST(BezierNets, NlsaFromItsTangentsIsPhongWithAlphaOneHalf) {
  test::Lcg rng(3);
  InterpolantParams half;
  half.phong_alpha = 0.5;
  for (int trial = 0; trial < 200; ++trial) {
    const Triangle t = random_triangle(rng);
    const QuadraticNet<double> nlsa = quadratic_net(Interpolant::NLSA, t.p, t.n, half);
    const QuadraticNet<double> phong = quadratic_net(Interpolant::Phong, t.p, t.n, half);
    for (int b = 0; b < 6; ++b) EXPECT_LT(glm::length(nlsa.b[b] - phong.b[b]), 1e-13) << b;
    // The construction itself differs: alpha = 3/4 does not agree.
    const QuadraticNet<double> phong34 = quadratic_net(Interpolant::Phong, t.p, t.n, InterpolantParams{});
    EXPECT_GT(glm::length(nlsa.b[1] - phong34.b[1]) + glm::length(nlsa.b[2] - phong34.b[2]) +
                  glm::length(nlsa.b[4] - phong34.b[4]),
              1e-6);
  }
}

TEST(BezierNets, NlsaWithParallelNormalsIsTheEdgeMidpoint) {
  // Tangents vanish: the parallel limit, not noise divided by noise.
  const glm::vec3 n = glm::normalize(glm::vec3(0.3f, 0.9f, 0.1f));
  const glm::vec3 p0(0.0f), p1(1.0f, 0.7f, -0.2f);  // an edge that leans against the normals
  const glm::vec3 b = nlsa_edge_point(p0, n, p1, n);
  EXPECT_EQ(b, (p0 + p1) / 2.0f);
  EXPECT_LT(glm::length(phong_edge_point(p0, n, p1, n, 0.5f) - b), 1e-6f);
}

TEST(BezierNets, PhongWithAlphaOneThirdAveragesThePnTangentCoefficients) {
  // Seed 004 Sec. 2.2: b110 of Phong(1/3) = (b210 + b120)/2 of PN.
  test::Lcg rng(4);
  for (int trial = 0; trial < 50; ++trial) {
    const Triangle t = random_triangle(rng);
    const dvec3 phong = phong_edge_point(t.p[0], t.n[0], t.p[1], t.n[1], 1.0 / 3.0);
    const dvec3 pn = (pn_tangent_point(t.p[0], t.n[0], t.p[1]) + pn_tangent_point(t.p[1], t.n[1], t.p[0])) / 2.0;
    EXPECT_LT(glm::length(phong - pn), 1e-14);
  }
}

TEST(BezierNets, PhongAlphaZeroAndFaceNormalsGiveTheFlatTriangle) {
  test::Lcg rng(5);
  const Triangle t = random_triangle(rng);
  InterpolantParams flat;
  flat.phong_alpha = 0.0;
  const QuadraticNet<double> q = quadratic_net(Interpolant::Phong, t.p, t.n, flat);
  EXPECT_EQ(q.b[QuadraticNet<double>::index(1, 1, 0)], (t.p[0] + t.p[1]) / 2.0);
  // Every scheme keeps a triangle whose normals are its face normal flat.
  Triangle f = t;
  const dvec3 face = glm::normalize(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]));
  for (auto& n : f.n) n = face;
  for (Interpolant s : kAll) {
    const CubicNet<double> net = cubic_net(s, f.p, f.n, InterpolantParams{});
    for (const dvec3& b : net.b) EXPECT_LT(std::fabs(glm::dot(b - f.p[0], face)), 1e-14) << name(s);
  }
}

TEST(BezierNets, NagataNearParallelNormalsBlowUpWithoutEpsAndStayBoundedWithIt) {
  // Seed 004 Fig. 8: tangent planes nearly parallel, the edge leaning against them; their
  // intersection line (and b110 on it) runs off as the angle closes.
  const dvec3 p0(0.0), p1(1.0, 0.0, 0.0);
  const dvec3 n0 = glm::normalize(dvec3(-0.5, 1.0, 0.0));  // leans 27 degrees against the edge
  const double edge = glm::length(p1 - p0);
  for (double angle : {1e-2, 1e-3, 1e-5}) {
    const dvec3 n1 = glm::normalize(n0 + angle * dvec3(0.0, 0.0, 1.0));
    const dvec3 raw = nagata_edge_point(p0, n0, p1, n1, 0.0);
    EXPECT_GT(glm::length(raw - (p0 + p1) / 2.0), 0.1 / angle * edge) << angle;
    // With the threshold the edge stays the straight segment (c1 = 0).
    const dvec3 cut = nagata_edge_point(p0, n0, p1, n1, 0.04);
    EXPECT_EQ(cut, (p0 + p1) / 2.0) << angle;
  }
  // The default threshold cuts what float rounding alone decides: normals parallel to float
  // precision give dc of order 1e-8, which 1e-4 removes.
  const glm::vec3 nf = glm::normalize(glm::vec3(-0.5f, 1.0f, 0.0f));
  const glm::vec3 nf1 = glm::normalize(nf + glm::vec3(0.0f, 0.0f, 3e-4f));
  const glm::vec3 q0(0.0f), q1(1.0f, 0.0f, 0.0f);
  EXPECT_EQ(nagata_curvature(q0, nf, q1, nf1, float(kDefaultNagataEps)), glm::vec3(0.0f));
  EXPECT_EQ(nagata_curvature(q0, nf, q1, nf, float(kDefaultNagataEps)), glm::vec3(0.0f));
  // Antiparallel normals: the other denominator.
  const dvec3 anti = -glm::normalize(n0 + 1e-5 * dvec3(0.0, 0.0, 1.0));
  EXPECT_GT(glm::length(nagata_curvature(p0, n0, p1, anti, 0.0)), 1e3);
  EXPECT_EQ(nagata_curvature(p0, n0, p1, anti, kDefaultNagataEps), dvec3(0.0));
  EXPECT_EQ(nagata_curvature(p0, n0, p1, -n0, 0.0), dvec3(0.0));
}

TEST(BezierNets, NagataEdgeCurveIsOrthogonalToBothNormals) {
  test::Lcg rng(6);
  for (int trial = 0; trial < 50; ++trial) {
    const Triangle t = random_triangle(rng);
    const dvec3 d = t.p[1] - t.p[0];
    const dvec3 c1 = nagata_curvature(t.p[0], t.n[0], t.p[1], t.n[1], 0.0);
    EXPECT_LT(std::fabs(glm::dot(d - c1, t.n[0])), 1e-12);  // x'(0) = d - c1
    EXPECT_LT(std::fabs(glm::dot(d + c1, t.n[1])), 1e-12);  // x'(1) = d + c1
  }
}

TEST(BezierNets, EdgeRulesAreSymmetricBitForBit) {
  // Both patches of an edge see its ends in opposite orders: the same bits either way.
  test::Lcg rng(7);
  for (int trial = 0; trial < 500; ++trial) {
    const Triangle t = random_triangle(rng);
    const glm::vec3 a = glm::vec3(t.p[0]), b = glm::vec3(t.p[1]);
    const glm::vec3 na = glm::vec3(t.n[0]), nb = glm::vec3(t.n[1]);
    EXPECT_EQ(phong_edge_point(a, na, b, nb, 0.75f), phong_edge_point(b, nb, a, na, 0.75f));
    EXPECT_EQ(nlsa_edge_point(a, na, b, nb), nlsa_edge_point(b, nb, a, na));
    EXPECT_EQ(nagata_edge_point(a, na, b, nb, 1e-4f), nagata_edge_point(b, nb, a, na, 1e-4f));
    EXPECT_EQ(quadratic_normal_mid(a, na, b, nb, false), quadratic_normal_mid(b, nb, a, na, false));
    EXPECT_EQ(quadratic_normal_mid(a, na, b, nb, true), quadratic_normal_mid(b, nb, a, na, true));
  }
}

TEST(BezierNets, DegreeElevationKeepsTheSurface) {
  test::Lcg rng(8);
  const Triangle t = random_triangle(rng);
  for (Interpolant s : {Interpolant::Phong, Interpolant::NLSA, Interpolant::Nagata}) {
    const QuadraticNet<double> q = quadratic_net(s, t.p, t.n, InterpolantParams{});
    const CubicNet<double> c = elevate(q);
    for (double u : {0.0, 0.2, 0.5})
      for (double v : {0.0, 0.3, 0.5}) {
        const SurfacePoint<double> a = evaluate(q, u, v), b = evaluate(c, u, v);
        EXPECT_LT(glm::length(a.position - b.position), 1e-14);
        EXPECT_LT(glm::length(a.du - b.du), 1e-13);
        EXPECT_LT(glm::length(a.dvv - b.dvv), 1e-12);
      }
  }
  EXPECT_THROW(quadratic_net(Interpolant::PN, t.p, t.n, InterpolantParams{}), std::invalid_argument);
}

TEST(BezierNets, DerivativesMatchCentralDifferences) {
  test::Lcg rng(9);
  const double h = 1e-5;
  for (int trial = 0; trial < 20; ++trial) {
    const Triangle t = random_triangle(rng);
    for (Interpolant s : kAll) {
      const CubicNet<double> net = cubic_net(s, t.p, t.n, InterpolantParams{});
      for (const auto& [u, v] : {std::pair{0.2, 0.3}, std::pair{0.6, 0.1}, std::pair{0.1, 0.1},
                                std::pair{0.33, 0.33}}) {
        auto at = [&](double du, double dv) { return evaluate(net, u + du, v + dv); };
        const SurfacePoint<double> c = at(0, 0);
        const dvec3 fu = (at(h, 0).position - at(-h, 0).position) / (2 * h);
        const dvec3 fv = (at(0, h).position - at(0, -h).position) / (2 * h);
        const dvec3 fuu = (at(h, 0).du - at(-h, 0).du) / (2 * h);
        const dvec3 fuv = (at(0, h).du - at(0, -h).du) / (2 * h);
        const dvec3 fvu = (at(h, 0).dv - at(-h, 0).dv) / (2 * h);
        const dvec3 fvv = (at(0, h).dv - at(0, -h).dv) / (2 * h);
        const std::string what = name(s) + " at " + std::to_string(u) + "," + std::to_string(v);
        EXPECT_LT(glm::length(c.du - fu), 1e-8) << what;
        EXPECT_LT(glm::length(c.dv - fv), 1e-8) << what;
        EXPECT_LT(glm::length(c.duu - fuu), 1e-7) << what;
        EXPECT_LT(glm::length(c.duv - fuv), 1e-7) << what;
        EXPECT_LT(glm::length(c.duv - fvu), 1e-7) << what;
        EXPECT_LT(glm::length(c.dvv - fvv), 1e-7) << what;
      }
    }
  }
}

TEST(BezierNets, AnalyticNormalFollowsTheCornerOrderAndAgreesAtPnCorners) {
  test::Lcg rng(10);
  const Triangle t = random_triangle(rng);
  const CubicNet<double> net = cubic_net(Interpolant::PN, t.p, t.n, InterpolantParams{});
  // PN reproduces the corner tangent planes, so its analytic normal there is the corner normal
  // (the random normals lean towards the counter-clockwise face normal).
  const double uv[3][2] = {{0, 0}, {1, 0}, {0, 1}};
  for (int c = 0; c < 3; ++c)
    EXPECT_GT(glm::dot(analytic_normal(evaluate(net, uv[c][0], uv[c][1])), t.n[c]), 1.0 - 1e-12);
  SurfacePoint<double> zero{};
  EXPECT_EQ(analytic_normal(zero), dvec3(0.0));
}

TEST(BezierNets, PnNetIsThePnControlProgramsBitForBit) {
  // "PN as stages/schemes/pn_triangles.cpp computes it": the same control points in float.
  test::Lcg rng(11);
  for (int trial = 0; trial < 100; ++trial) {
    const Triangle t = random_triangle(rng);
    glm::vec3 p[3], n[3];
    for (int c = 0; c < 3; ++c) p[c] = glm::vec3(t.p[c]), n[c] = glm::vec3(t.n[c]);
    PnTcs tcs;
    const PatchOutput out = test::run_tcs(
        tcs, test::make_patch({test::vertex(p[0], n[0]), test::vertex(p[1], n[1]), test::vertex(p[2], n[2])}));
    auto attr = [&](int v, int slot) { return glm::vec3(out.vertices[v].attr[slot]); };
    for (int c = 0; c < 3; ++c) n[c] = attr(c, kAttrNormal);  // the program's own normalization
    const CubicNet<float> net = cubic_net(Interpolant::PN, p, n, InterpolantParams{});
    using C = CubicNet<float>;
    EXPECT_EQ(net.b[C::index(2, 1, 0)], attr(0, kPnAttrTangentNext));
    EXPECT_EQ(net.b[C::index(2, 0, 1)], attr(0, kPnAttrTangentPrev));
    EXPECT_EQ(net.b[C::index(0, 2, 1)], attr(1, kPnAttrTangentNext));
    EXPECT_EQ(net.b[C::index(1, 2, 0)], attr(1, kPnAttrTangentPrev));
    EXPECT_EQ(net.b[C::index(1, 0, 2)], attr(2, kPnAttrTangentNext));
    EXPECT_EQ(net.b[C::index(0, 1, 2)], attr(2, kPnAttrTangentPrev));
    EXPECT_EQ(net.b[C::index(1, 1, 1)], glm::vec3(out.patch[kPnPatchCenter]));
  }
}

}  // namespace
}  // namespace tessref
