// PN triangles: the control net, the four normal fields, degenerate input.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/constants.hpp>

#include "stages/schemes/canonical.h"
#include "tess_test_util.h"

namespace tessref {
namespace {

using namespace test;  // tess_test_util.h

PatchOutput pn_net(const std::vector<StageVertex>& vs, PnNormalMode mode) {
  PnTcs tcs;
  tcs.normal_mode = mode;
  return run_tcs(tcs, make_patch(vs));
}

double angle(const glm::dvec3& a, const glm::dvec3& b) {
  // atan2 of |a x b| and a.b: accurate for tiny angles, unlike acos.
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// An independent double-precision PN surface straight from formulas.md (P1, P2, P3 with weights
// w, u, v), written in the multinomial Bernstein form, for checking the float code.
struct RefPn {
  glm::dvec3 P[3], N[3], b[4][4][4]{};  // b[i][j][k]: exponents of w, u, v; i + j + k = 3

  RefPn(const std::vector<StageVertex>& vs) {
    for (int i = 0; i < 3; ++i) {
      P[i] = glm::dvec3(glm::vec3(vs[i].attr[0]));
      N[i] = glm::normalize(glm::dvec3(glm::vec3(vs[i].attr[1])));
    }
    auto t = [&](int i, int j) {
      const double w = glm::dot(P[j] - P[i], N[i]);
      return (2.0 * P[i] + P[j] - w * N[i]) / 3.0;
    };
    b[3][0][0] = P[0];
    b[0][3][0] = P[1];
    b[0][0][3] = P[2];
    b[2][1][0] = t(0, 1);
    b[1][2][0] = t(1, 0);
    b[0][2][1] = t(1, 2);
    b[0][1][2] = t(2, 1);
    b[1][0][2] = t(2, 0);
    b[2][0][1] = t(0, 2);
    const glm::dvec3 E = (b[2][1][0] + b[1][2][0] + b[0][2][1] + b[0][1][2] + b[1][0][2] +
                          b[2][0][1]) / 6.0;
    const glm::dvec3 V = (P[0] + P[1] + P[2]) / 3.0;
    b[1][1][1] = E + (E - V) / 2.0;
  }
  // Quadratic normal field (formulas.md), k = 2 with normalized mid-edge normals (Vlachos) or
  // k = 4 unnormalized (corrected).
  glm::dvec3 quadratic_normal(double w, double u, double v, bool corrected) const {
    auto mid = [&](int i, int j) {
      const glm::dvec3 d = P[j] - P[i];
      const double k = corrected ? 4.0 : 2.0;
      const glm::dvec3 h = N[i] + N[j] - (k * glm::dot(d, N[i] + N[j]) / glm::dot(d, d)) * d;
      return corrected ? h : glm::normalize(h);
    };
    const glm::dvec3 n = N[0] * (w * w) + N[1] * (u * u) + N[2] * (v * v) + mid(0, 1) * (w * u) +
                         mid(1, 2) * (u * v) + mid(2, 0) * (w * v);
    return glm::normalize(n);
  }
  glm::dvec3 eval(double w, double u, double v) const {
    static const double fact[4] = {1, 1, 2, 6};
    glm::dvec3 s(0.0);
    for (int i = 0; i <= 3; ++i)
      for (int j = 0; i + j <= 3; ++j) {
        const int k = 3 - i - j;
        s += b[i][j][k] * (6.0 / (fact[i] * fact[j] * fact[k]) * std::pow(w, i) * std::pow(u, j) *
                           std::pow(v, k));
      }
    return s;
  }
  // Surface normal by central differences along the domain, oriented by the right-hand rule on
  // the corner order (t1 moves weight from P1 to P2, t2 from P1 to P3).
  glm::dvec3 fd_normal(double t1, double t2) const {
    const double h = 1e-4;
    auto at = [&](double a, double b) { return eval(1.0 - a - b, a, b); };
    const glm::dvec3 d1 = (at(t1 + h, t2) - at(t1 - h, t2)) / (2 * h);
    const glm::dvec3 d2 = (at(t1, t2 + h) - at(t1, t2 - h)) / (2 * h);
    return glm::normalize(glm::cross(d1, d2));
  }
};

std::vector<StageVertex> random_triangle(Lcg& rng) {
  // A CCW triangle around +z with normals tilted up to ~40 degrees off the face normal.
  std::vector<StageVertex> vs;
  const glm::vec3 base[3] = {{0, 0, 0}, {1, 0, 0}, {0.3f, 0.9f, 0}};
  for (int i = 0; i < 3; ++i) {
    const glm::vec3 p = base[i] + rng.vec(-0.2f, 0.2f);
    const glm::vec3 n = glm::normalize(glm::vec3(0, 0, 1) + rng.vec(-0.7f, 0.7f) * glm::vec3(1, 1, 0));
    vs.push_back(vertex(p, n));
  }
  return vs;
}

TEST(PnTriangles, InterpolatesCornersAndTheirNormals) {
  Lcg rng(1);
  for (int trial = 0; trial < 20; ++trial) {
    const auto vs = random_triangle(rng);
    for (PnNormalMode mode : kPnNormalModes) {
      const PatchOutput net = pn_net(vs, mode);
      for (int c = 0; c < 3; ++c) {
        glm::vec3 tc(0.0f);
        tc[c] = 1.0f;  // gl_TessCoord component c weighs gl_in[c]
        const glm::vec3 p = pn_position(net, tc);
        EXPECT_TRUE(same_bits(p, glm::vec3(vs[c].attr[0]))) << "corner " << c;
        const glm::vec3 n = pn_normal(net, tc, mode);
        const glm::vec3 expect = glm::normalize(glm::vec3(vs[c].attr[1]));
        const float tol = mode == PnNormalMode::Analytic ? 1e-5f : 1e-6f;
        EXPECT_NEAR(glm::length(n - expect), 0.0f, tol) << to_string(mode) << " corner " << c;
      }
    }
  }
}

TEST(PnTriangles, AxisNormalsAreExactAtCorners) {
  const std::vector<StageVertex> vs = {vertex({0, 0, 0}, {0, 0, 1}), vertex({1, 0, 0}, {1, 0, 0}),
                                       vertex({0, 1, 0}, {0, 1, 0})};
  for (PnNormalMode mode : {PnNormalMode::Linear, PnNormalMode::Quadratic,
                            PnNormalMode::QuadraticCorrected}) {
    const PatchOutput net = pn_net(vs, mode);
    for (int c = 0; c < 3; ++c) {
      glm::vec3 tc(0.0f);
      tc[c] = 1.0f;
      EXPECT_EQ(pn_normal(net, tc, mode), glm::vec3(vs[c].attr[1])) << to_string(mode);
    }
  }
}

TEST(PnTriangles, MatchesTheReferenceFormulas) {
  Lcg rng(2);
  for (int trial = 0; trial < 20; ++trial) {
    const auto vs = random_triangle(rng);
    const RefPn ref(vs);
    const PatchOutput net = pn_net(vs, PnNormalMode::Quadratic);
    for (int i = 0; i <= 8; ++i)
      for (int j = 0; i + j <= 8; ++j) {
        const float u = float(i) / 8, v = float(j) / 8;
        const glm::vec3 tc((1.0f - u) - v, u, v);
        const glm::dvec3 p = ref.eval(tc.x, tc.y, tc.z);
        EXPECT_LT(glm::length(glm::dvec3(pn_position(net, tc)) - p), 1e-6);
      }
  }
}

TEST(PnTriangles, QuadraticNormalsMatchTheReferenceFormulas) {
  Lcg rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    const auto vs = random_triangle(rng);
    const RefPn ref(vs);
    for (bool corrected : {false, true}) {
      const PnNormalMode mode = corrected ? PnNormalMode::QuadraticCorrected : PnNormalMode::Quadratic;
      const PatchOutput net = pn_net(vs, mode);
      for (int i = 0; i <= 8; ++i)
        for (int j = 0; i + j <= 8; ++j) {
          const float u = float(i) / 8, v = float(j) / 8;
          const glm::vec3 tc((1.0f - u) - v, u, v);
          const glm::dvec3 n(pn_normal(net, tc, mode));
          EXPECT_LT(angle(n, ref.quadratic_normal(tc.x, tc.y, tc.z, corrected)), 1e-6)
              << to_string(mode);
        }
    }
  }
}

TEST(PnTriangles, FlatTriangleWithFaceNormalsStaysFlat) {
  // A tilted plane: all points must stay on it, all normals equal the face normal.
  const glm::vec3 p0(0.2f, -0.1f, 0.3f), p1(1.1f, 0.2f, -0.4f), p2(0.1f, 0.9f, 0.5f);
  const glm::vec3 face = glm::normalize(glm::cross(p1 - p0, p2 - p0));
  for (bool reversed : {false, true}) {
    // Reversed: clockwise corner order with the same normals (the analytic orientation check).
    const std::vector<StageVertex> vs =
        reversed ? std::vector<StageVertex>{vertex(p0, face), vertex(p2, face), vertex(p1, face)}
                 : std::vector<StageVertex>{vertex(p0, face), vertex(p1, face), vertex(p2, face)};
    for (PnNormalMode mode : kPnNormalModes) {
      const PatchOutput net = pn_net(vs, mode);
      for (int i = 0; i <= 16; ++i)
        for (int j = 0; i + j <= 16; ++j) {
          const float u = float(i) / 16, v = float(j) / 16;
          const glm::vec3 tc((1.0f - u) - v, u, v);
          const glm::vec3 p = pn_position(net, tc);
          EXPECT_LE(std::abs(glm::dot(p - p0, face)), 1e-6f) << to_string(mode);
          EXPECT_LE(glm::length(pn_normal(net, tc, mode) - face), 1e-6f)
              << to_string(mode) << " reversed " << reversed << " at " << u << "," << v;
        }
    }
  }
}

TEST(PnTriangles, AnalyticNormalsMatchFiniteDifferences) {
  Lcg rng(3);
  double worst = 0.0;
  for (int trial = 0; trial < 50; ++trial) {
    const auto vs = random_triangle(rng);
    const RefPn ref(vs);
    const PatchOutput net = pn_net(vs, PnNormalMode::Analytic);
    for (int i = 1; i < 10; ++i)
      for (int j = 1; i + j < 10; ++j) {
        const float t1 = float(i) / 10, t2 = float(j) / 10;
        const glm::vec3 tc((1.0f - t1) - t2, t1, t2);
        const glm::dvec3 n(pn_normal(net, tc, PnNormalMode::Analytic));
        const glm::dvec3 fd = ref.fd_normal(tc.y, tc.z);
        worst = std::max(worst, angle(n, fd));
      }
  }
  EXPECT_LT(worst, 1e-5) << "radians";
}

TEST(PnTriangles, AnalyticNormalsFollowTheInputOrientation) {
  // Clockwise corner order: the derivative cross product points away from the input normals,
  // so the analytic normal must be flipped to agree with them.
  Lcg rng(4);
  for (int trial = 0; trial < 20; ++trial) {
    auto vs = random_triangle(rng);
    std::swap(vs[1], vs[2]);
    const RefPn ref(vs);
    const PatchOutput net = pn_net(vs, PnNormalMode::Analytic);
    const glm::vec3 tc(0.2f, 0.5f, 0.3f);
    const glm::dvec3 n(pn_normal(net, tc, PnNormalMode::Analytic));
    EXPECT_GT(n.z, 0.0);
    EXPECT_LT(angle(n, -ref.fd_normal(tc.y, tc.z)), 1e-5);
  }
}

TEST(PnTriangles, NormalModesDifferOnAnInflectedEdge) {
  // Both edge normals tilted the same way (towards +x): the cubic edge curve from P0 to P1 dips,
  // then rises: an inflection. The reflected mid-edge normal captures it.
  const float s = 0.5f;
  const glm::vec3 tilt = glm::normalize(glm::vec3(s, 0, 1));
  const std::vector<StageVertex> vs = {vertex({0, 0, 0}, tilt), vertex({1, 0, 0}, tilt),
                                       vertex({0.5f, 1, 0}, {0, 0, 1})};
  const glm::vec3 mid(0.5f, 0.5f, 0.0f);
  glm::vec3 n[4];
  for (int m = 0; m < 4; ++m) n[m] = pn_normal(pn_net(vs, kPnNormalModes[m]), mid, kPnNormalModes[m]);
  const glm::vec3 &lin = n[0], &quad = n[1], &corr = n[2], &ana = n[3];

  // Corrected: exactly the average normal reflected across the plane perpendicular to the edge.
  EXPECT_LT(glm::length(corr - glm::normalize(glm::vec3(-tilt.x, 0, tilt.z))), 1e-6f);
  // Linear: the unreflected average (the tilt itself).
  EXPECT_LT(glm::length(lin - tilt), 1e-6f);
  // The true surface normal leans against the tilt at the midpoint (the curve rises there).
  EXPECT_LT(ana.x, 0.0f);
  EXPECT_LT(corr.x, 0.0f);
  EXPECT_GT(lin.x, 0.0f);
  auto ang = [](glm::vec3 a, glm::vec3 b) { return angle(glm::dvec3(a), glm::dvec3(b)); };
  EXPECT_GT(ang(quad, corr), 0.05);
  EXPECT_GT(ang(lin, quad), 0.05);
  EXPECT_GT(ang(lin, corr), 0.05);
  // Vlachos' normalized n110 lands between the linear and the reflected directions.
  EXPECT_LT(ang(quad, corr), ang(lin, corr));

  // Without an inflection (normals tilted apart: a convex arc) reflection changes nothing along
  // the edge direction: quadratic and linear agree at the midpoint.
  const std::vector<StageVertex> arc = {
      vertex({0, 0, 0}, glm::normalize(glm::vec3(-s, 0, 1))),
      vertex({1, 0, 0}, glm::normalize(glm::vec3(s, 0, 1))), vertex({0.5f, 1, 0}, {0, 0, 1})};
  const glm::vec3 nl = pn_normal(pn_net(arc, PnNormalMode::Linear), mid, PnNormalMode::Linear);
  const glm::vec3 nq = pn_normal(pn_net(arc, PnNormalMode::Quadratic), mid, PnNormalMode::Quadratic);
  EXPECT_LT(glm::length(nl - nq), 1e-6f);
}

TEST(PnTriangles, DegenerateInputGivesNoNaN) {
  const std::vector<std::vector<StageVertex>> cases = {
      // zero normals
      {vertex({0, 0, 0}, {0, 0, 0}), vertex({1, 0, 0}, {0, 0, 0}), vertex({0, 1, 0}, {0, 0, 0})},
      // all corners equal
      {vertex({1, 1, 1}, {0, 0, 1}), vertex({1, 1, 1}, {0, 0, 1}), vertex({1, 1, 1}, {0, 0, 1})},
      // zero-length edge, opposite normals
      {vertex({0, 0, 0}, {0, 0, 1}), vertex({0, 0, 0}, {0, 0, -1}), vertex({0, 1, 0}, {1, 0, 0})},
      // collinear corners
      {vertex({0, 0, 0}, {0, 0, 1}), vertex({1, 0, 0}, {0, 0, 1}), vertex({2, 0, 0}, {0, 0, 1})},
  };
  for (const auto& vs : cases)
    for (PnNormalMode mode : kPnNormalModes) {
      const PatchOutput net = pn_net(vs, mode);
      for (int i = 0; i <= 4; ++i)
        for (int j = 0; i + j <= 4; ++j) {
          const glm::vec3 tc((1.0f - i / 4.0f) - j / 4.0f, i / 4.0f, j / 4.0f);
          const glm::vec3 p = pn_position(net, tc), n = pn_normal(net, tc, mode);
          for (int c = 0; c < 3; ++c) {
            EXPECT_TRUE(std::isfinite(p[c])) << to_string(mode);
            EXPECT_TRUE(std::isfinite(n[c])) << to_string(mode);
          }
          const float len = glm::length(n);
          EXPECT_TRUE(len == 0.0f || std::abs(len - 1.0f) < 1e-5f) << to_string(mode);
        }
    }
}

TEST(PnTriangles, NormalModeNames) {
  for (PnNormalMode m : kPnNormalModes) {
    PnNormalMode back{};
    ASSERT_TRUE(parse(to_string(m), back));
    EXPECT_EQ(back, m);
  }
  PnNormalMode x;
  EXPECT_FALSE(parse("fake", x));
}

TEST(Canonical, OrderDependsOnDataOnly) {
  const std::array<glm::vec3, 3> p{glm::vec3(1, 0, 0), glm::vec3(0, 2, 0), glm::vec3(0, 1, 0)};
  const std::array<glm::vec3, 3> n{glm::vec3(0), glm::vec3(0), glm::vec3(0)};
  const auto o = canonical_corner_order(p, n);
  // Rotating the corners rotates the order: the same data comes out first.
  const std::array<glm::vec3, 3> p2{p[1], p[2], p[0]};
  const auto o2 = canonical_corner_order(p2, n);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(p[o[i]], p2[o2[i]]);
}

}  // namespace
}  // namespace tessref
