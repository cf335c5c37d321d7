// Phong tessellation, NLSA and Nagata triangles as built-in programs (phong.h, nlsa.h, nagata.h over
// quadratic_patch.h): corner interpolation, the nets of bezier_nets.h bit for bit, positions against
// its double-precision evaluation, shared edges bit-identical through the executor, evaluate_batch
// equal to evaluate, and no NaN from degenerate corners.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "stages/schemes/bezier_nets.h"
#include "stages/schemes/nagata.h"
#include "stages/schemes/nlsa.h"
#include "stages/schemes/phong.h"
#include "stages/schemes/quadratic_patch.h"
#include "tess_test_util.h"

namespace tessref {
namespace {

using namespace test;  // tess_test_util.h

enum class Scheme { Phong, Nlsa, Nagata };
constexpr Scheme kSchemes[] = {Scheme::Phong, Scheme::Nlsa, Scheme::Nagata};
std::string name(Scheme s) { return s == Scheme::Phong ? "phong" : s == Scheme::Nlsa ? "nlsa" : "nagata"; }
schemes::Interpolant interpolant(Scheme s) {
  return s == Scheme::Phong ? schemes::Interpolant::Phong
                            : s == Scheme::Nlsa ? schemes::Interpolant::NLSA : schemes::Interpolant::Nagata;
}

// Non-default parameters, so that a program that ignored them would be caught.
constexpr float kAlpha = 0.6f, kEps = 0.01f;

std::unique_ptr<QuadraticTcs> make_tcs(Scheme s, PnNormalMode mode, float level = 4.0f,
                                       float eps = kEps) {
  std::unique_ptr<QuadraticTcs> tcs;
  if (s == Scheme::Phong) {
    auto p = std::make_unique<PhongTcs>();
    p->alpha = kAlpha;
    tcs = std::move(p);
  } else if (s == Scheme::Nlsa) {
    tcs = std::make_unique<NlsaTcs>();
  } else {
    auto n = std::make_unique<NagataTcs>();
    n->eps = eps;
    tcs = std::move(n);
  }
  tcs->normal_mode = mode;
  tcs->levels = TessLevelSettings::uniform(level, level);
  return tcs;
}

struct Tri {
  glm::vec3 p[3], n[3];
};
// Corners on a bumpy surface, normals leaning up to ~40 degrees off +z (not unit length: the
// control programs normalize).
Tri random_tri(Lcg& rng) {
  Tri t;
  t.p[0] = {0.0f, 0.0f, 0.0f};
  t.p[1] = {1.0f, rng.uniform(-0.2f, 0.2f), rng.uniform(-0.2f, 0.2f)};
  t.p[2] = {rng.uniform(-0.2f, 0.4f), 1.0f, rng.uniform(-0.2f, 0.2f)};
  for (auto& n : t.n) n = (rng.vec(-0.8f, 0.8f) + glm::vec3(0, 0, 1.5f)) * rng.uniform(0.5f, 2.0f);
  return t;
}
Patch patch_of(const Tri& t) {
  return make_patch({vertex(t.p[0], t.n[0]), vertex(t.p[1], t.n[1]), vertex(t.p[2], t.n[2])});
}

TEST(QuadraticSchemes, InterpolateCornersAndTheirNormals) {
  Lcg rng(1);
  for (int trial = 0; trial < 20; ++trial) {
    const Tri t = random_tri(rng);
    for (Scheme s : kSchemes)
      for (PnNormalMode mode : kPnNormalModes) {
        // Nagata without threshold: no edge straightened, every tangent plane kept.
        const PatchOutput out = run_tcs(*make_tcs(s, mode, 4.0f, 0.0f), patch_of(t));
        for (int c = 0; c < 3; ++c) {
          glm::vec3 tc(0.0f);
          tc[c] = 1.0f;
          const std::string what = name(s) + " " + to_string(mode) + " corner " + std::to_string(c);
          EXPECT_TRUE(same_bits(quadratic_position(out, tc), t.p[c])) << what;
          const glm::vec3 unit = safe_normalize(t.n[c]);
          const glm::vec3 n = quadratic_normal(out, tc, mode);
          if (mode != PnNormalMode::Analytic) {
            EXPECT_LT(glm::length(n - unit), 1e-6f) << what;
          } else if (s == Scheme::Nagata) {
            // Nagata reproduces the tangent planes (seed 004 Sec. 5): its own normal is N_i.
            EXPECT_GT(glm::dot(n, unit), 1.0f - 1e-5f) << what;
          }
        }
      }
  }
}

TEST(QuadraticSchemes, ControlPointsAreBezierNetsBitForBitAndPositionsItsSurface) {
  Lcg rng(2);
  schemes::InterpolantParams params;
  params.phong_alpha = kAlpha;
  params.nagata_eps = kEps;
  for (int trial = 0; trial < 20; ++trial) {
    const Tri t = random_tri(rng);
    for (Scheme s : kSchemes) {
      const PatchOutput out = run_tcs(*make_tcs(s, PnNormalMode::Linear), patch_of(t));
      glm::vec3 p[3], n[3];
      glm::dvec3 pd[3], nd[3];
      for (int c = 0; c < 3; ++c) {
        p[c] = glm::vec3(out.vertices[c].attr[kAttrPosition]);
        n[c] = glm::vec3(out.vertices[c].attr[kAttrNormal]);
        pd[c] = p[c], nd[c] = n[c];
      }
      const schemes::QuadraticNet<float> net = schemes::quadratic_net(interpolant(s), p, n, params);
      using Q = schemes::QuadraticNet<float>;
      auto edge = [&](int c) { return glm::vec3(out.vertices[c].attr[kQuadAttrEdgePoint]); };
      EXPECT_TRUE(same_bits(edge(0), net.b[Q::index(1, 1, 0)])) << name(s);
      EXPECT_TRUE(same_bits(edge(1), net.b[Q::index(0, 1, 1)])) << name(s);
      EXPECT_TRUE(same_bits(edge(2), net.b[Q::index(1, 0, 1)])) << name(s);
      // The TES's canonical-order sum against the double evaluation of the same net.
      const schemes::QuadraticNet<double> ref = schemes::quadratic_net(interpolant(s), pd, nd, params);
      for (int k = 0; k < 30; ++k) {
        const float u = rng.uniform(0.0f, 1.0f), v = rng.uniform(0.0f, 1.0f - u);
        const glm::vec3 tc(1.0f - u - v, u, v);
        const schemes::SurfacePoint<double> sp = schemes::evaluate(ref, double(u), double(v));
        EXPECT_LT(glm::length(glm::dvec3(quadratic_position(out, tc)) - sp.position), 1e-5) << name(s);
        glm::vec3 d1, d2;
        quadratic_derivatives(out, tc, d1, d2);
        EXPECT_LT(glm::length(glm::dvec3(d1) - sp.du), 1e-5) << name(s);
        EXPECT_LT(glm::length(glm::dvec3(d2) - sp.dv), 1e-5) << name(s);
        const glm::vec3 na = quadratic_normal(out, tc, PnNormalMode::Analytic);
        EXPECT_GT(std::fabs(glm::dot(glm::dvec3(na), schemes::analytic_normal(sp))), 1.0 - 1e-5) << name(s);
      }
    }
  }
}

TEST(QuadraticSchemes, NlsaProgramDrawsPhongWithAlphaOneHalf) {
  Lcg rng(3);
  for (int trial = 0; trial < 20; ++trial) {
    const Tri t = random_tri(rng);
    PhongTcs phong;
    phong.alpha = 0.5f;
    const PatchOutput a = run_tcs(phong, patch_of(t));
    const PatchOutput b = run_tcs(*make_tcs(Scheme::Nlsa, PnNormalMode::Quadratic), patch_of(t));
    for (int k = 0; k < 20; ++k) {
      const float u = rng.uniform(0.0f, 1.0f), v = rng.uniform(0.0f, 1.0f - u);
      const glm::vec3 tc(1.0f - u - v, u, v);
      EXPECT_LT(glm::length(quadratic_position(a, tc) - quadratic_position(b, tc)), 1e-5f);
    }
  }
}

TEST(QuadraticSchemes, ParametersReachTheSurface) {
  // Phong alpha = 0 is the flat triangle; Nagata's eps = 0.5 straightens every edge.
  Lcg rng(4);
  const Tri t = random_tri(rng);
  PhongTcs flat;
  flat.alpha = 0.0f;
  NagataTcs straight;
  straight.eps = 0.5f;
  for (const QuadraticTcs* tcs : {static_cast<const QuadraticTcs*>(&flat), static_cast<const QuadraticTcs*>(&straight)}) {
    const PatchOutput out = run_tcs(*tcs, patch_of(t));
    const glm::vec3 tc(0.2f, 0.3f, 0.5f);
    const glm::vec3 linear = t.p[0] * tc.x + t.p[1] * tc.y + t.p[2] * tc.z;
    EXPECT_LT(glm::length(quadratic_position(out, tc) - linear), 1e-6f);
  }
  const PatchOutput bulged = run_tcs(*make_tcs(Scheme::Phong, PnNormalMode::Linear), patch_of(t));
  EXPECT_GT(glm::length(quadratic_position(bulged, glm::vec3(0.2f, 0.3f, 0.5f)) -
                        (t.p[0] * 0.2f + t.p[1] * 0.3f + t.p[2] * 0.5f)),
            1e-3f);
}

TEST(QuadraticSchemes, SharedEdgesAreBitIdenticalInBothPatches) {
  // All three schemes guarantee C0 from the edge's own data. Patch 0 = (A, B, C), patch 1 =
  // (B, A, D): the edge A-B runs in opposite directions and sits in different slots; the extra
  // patches rotate it through every slot placement.
  Lcg rng(5);
  for (int trial = 0; trial < 4; ++trial) {
    const glm::vec3 A = rng.vec(-1, 1), B = rng.vec(-1, 1), C = rng.vec(-1, 1), D = rng.vec(-1, 1);
    auto nrm = [&]() { return rng.vec(-1, 1) + glm::vec3(0, 0, 2); };
    const std::vector<StageVertex> vs = {vertex(A, nrm()), vertex(B, nrm()), vertex(C, nrm()), vertex(D, nrm())};
    const std::vector<std::uint32_t> idx = {0, 1, 2, 1, 0, 3, 3, 1, 0, 0, 3, 1};
    const int opposite[4] = {2, 2, 0, 1};
    for (Scheme s : kSchemes)
      for (TessSpacing spacing : {TessSpacing::Equal, TessSpacing::FractionalOdd, TessSpacing::FractionalEven})
        for (float level : {1.0f, 3.7f, 8.0f})
          for (PnNormalMode mode : kPnNormalModes) {
            const auto tcs = make_tcs(s, mode, level);
            QuadraticTes tes;
            tes.normal_mode = mode;
            tes.spacing = spacing;
            const auto dump = tessellate_dump(TessDrawInput{vs, idx, 3}, 4, *tcs, tes);
            const auto ref = edge_points(dump, 0, opposite[0]);
            ASSERT_GE(ref.size(), 2u);
            const std::string what = name(s) + " " + to_string(spacing) + " level " +
                                     std::to_string(level) + " " + to_string(mode);
            for (std::uint32_t p = 1; p < 4; ++p) {
              const auto other = edge_points(dump, p, opposite[p]);
              ASSERT_EQ(other.size(), ref.size()) << what;
              for (std::size_t i = 0; i < ref.size(); ++i) {
                EXPECT_TRUE(same_bits(std::get<0>(other[i]), std::get<0>(ref[i])))
                    << what << " patch " << p << " point " << i;
                // Analytic normals depend on the cross-edge derivative: C0 patches differ there.
                if (mode != PnNormalMode::Analytic) {
                  EXPECT_TRUE(same_bits(std::get<1>(other[i]), std::get<1>(ref[i]))) << what << " patch " << p;
                }
              }
            }
          }
  }
}

TEST(QuadraticSchemes, BatchEqualsEvaluateBitForBit) {
  Lcg rng(6);
  const Tri t = random_tri(rng);
  for (PnNormalMode mode : kPnNormalModes) {
    const PatchOutput out = run_tcs(*make_tcs(Scheme::Nagata, mode), patch_of(t));
    QuadraticTes tes;
    tes.normal_mode = mode;
    tes.view_proj = glm::mat4(1.0f, 0.1f, 0.0f, 0.0f, 0.0f, 0.9f, 0.2f, 0.0f, 0.0f, 0.0f, 1.1f, 1.0f,
                              0.3f, -0.2f, 2.0f, 3.0f);
    std::vector<float> coord[3];
    for (int i = 0; i < 37; ++i) {
      const float u = rng.uniform(0.0f, 1.0f), v = rng.uniform(0.0f, 1.0f - u);
      coord[0].push_back(1.0f - u - v), coord[1].push_back(u), coord[2].push_back(v);
    }
    TessEvalBatch batch;
    batch.count = 37;
    for (int c = 0; c < 3; ++c) batch.tess_coord[c] = coord[c].data();
    tes.evaluate_batch(out, 0, batch);
    for (int i = 0; i < batch.count; ++i) {
      const ClipVertex v = tes.evaluate(glm::vec3(coord[0][i], coord[1][i], coord[2][i]), out, 0);
      for (int c = 0; c < 4; ++c) EXPECT_EQ(test::bits(batch.position[c][i]), test::bits(v.position[c]));
      for (int k = 0; k < kBuiltinVaryings; ++k)
        EXPECT_EQ(test::bits(batch.varyings[k][i]), test::bits(v.varyings[k])) << to_string(mode);
    }
  }
}

TEST(QuadraticSchemes, DegenerateCornersGiveNoNaN) {
  // Zero normals, a repeated corner, parallel and antiparallel normals: finite output.
  const std::vector<Tri> cases = {
      {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 0, 0}, {0, 0, 1}, {0, 0, 0}}},
      {{{0, 0, 0}, {0, 0, 0}, {0, 1, 0}}, {{0, 0, 1}, {0, 1, 1}, {1, 0, 1}}},
      {{{0, 0, 0}, {1, 0, 0.5f}, {0, 1, 0}}, {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}}},
      {{{0, 0, 0}, {1, 0, 0.5f}, {0, 1, 0}}, {{0, 0, 1}, {0, 0, -1}, {0, 1, 0}}},
  };
  for (const Tri& t : cases)
    for (Scheme s : kSchemes)
      for (PnNormalMode mode : kPnNormalModes) {
        const PatchOutput out = run_tcs(*make_tcs(s, mode), patch_of(t));
        for (const glm::vec3 tc : {glm::vec3(1, 0, 0), glm::vec3(0.2f, 0.3f, 0.5f), glm::vec3(0, 0.5f, 0.5f)}) {
          const glm::vec3 p = quadratic_position(out, tc), n = quadratic_normal(out, tc, mode);
          EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) << name(s);
          EXPECT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z)) << name(s) << " " << to_string(mode);
        }
      }
}

}  // namespace
}  // namespace tessref
