// Procedural displacement along the normal (stages/schemes/displacement.h): P + a sin(f |P|) N
// against a double-precision reference, the perturbed normal against the displaced surface's
// finite-difference normal on flat patches (where it is exact), the batch path equal to
// evaluate() bit for bit over PN and flat, shared edges still watertight, and the scene keys.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "common/error.h"
#include "scene/scene_loader.h"
#include "stages/schemes/displacement.h"
#include "tess_test_util.h"

namespace tessref {
namespace {

using namespace test;  // tess_test_util.h

glm::vec3 varying3(const ClipVertex& v, int at) { return {v.varyings[at], v.varyings[at + 1], v.varyings[at + 2]}; }

TEST(Displacement, MovesAlongTheNormalByASinFR) {
  const DisplacementSettings d{true, 0.1f, 2.0f};
  Lcg rng(7);
  for (int i = 0; i < 200; ++i) {
    glm::vec3 p = rng.vec(-3.0f, 3.0f), n = glm::normalize(rng.vec(-1.0f, 1.0f));
    const glm::dvec3 p0(p), n0(n);
    displace(d, p, n);
    const double r = glm::length(p0);
    const glm::dvec3 want = p0 + 0.1 * std::sin(2.0 * r) * n0;
    EXPECT_NEAR(glm::length(glm::dvec3(p) - want), 0.0, 2e-6) << i;
    EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
  }
  // A zero normal (degenerate input) moves nothing and stays zero.
  glm::vec3 p(1.0f, 2.0f, 3.0f), n(0.0f);
  displace(d, p, n);
  EXPECT_EQ(p, glm::vec3(1.0f, 2.0f, 3.0f));
  EXPECT_EQ(n, glm::vec3(0.0f));
}

// A flat patch in the plane z = 0.5 displaced by DisplacedTes over FlatTes.
struct FlatDisplaced {
  PassThroughTcs tcs;
  FlatTes flat;
  DisplacedTes tes;
  PatchOutput patch;
  FlatDisplaced(float a, float f) {
    flat.tess_layout = TessLayout{TessDomain::Triangles, TessSpacing::Equal, TessWinding::Ccw, false};
    tes.base = &flat;
    tes.displacement = DisplacementSettings{true, a, f};
    const glm::vec3 up(0.0f, 0.0f, 1.0f);
    patch = run_tcs(tcs, make_patch({vertex({-1.0f, -1.0f, 0.5f}, up), vertex({1.5f, -0.5f, 0.5f}, up),
                                     vertex({0.0f, 1.2f, 0.5f}, up)}));
  }
  glm::dvec3 at(const glm::dvec3& tc) const {
    return glm::dvec3(varying3(tes.evaluate(glm::vec3(tc), patch, 0), kVaryingPosition));
  }
};

TEST(Displacement, NormalIsTheDisplacedSurfacesOnAFlatPatch) {
  // h = a sin(f |P|) over a plane: the perturbed normal is the displaced surface's exactly, so it
  // matches central differences up to their O(step^2) error and float rounding.
  const FlatDisplaced s(0.05f, 6.0f);
  Lcg rng(3);
  double worst = 0.0, bent = 0.0;
  for (int i = 0; i < 100; ++i) {
    const double u = rng.uniform(0.1f, 0.8f), v = rng.uniform(0.05f, 0.9f - float(u));
    const glm::dvec3 tc(u, v, 1.0 - u - v);
    const double h = 1e-3;
    const glm::dvec3 du = s.at(tc + glm::dvec3(h, 0, -h)) - s.at(tc - glm::dvec3(h, 0, -h));
    const glm::dvec3 dv = s.at(tc + glm::dvec3(0, h, -h)) - s.at(tc - glm::dvec3(0, h, -h));
    glm::dvec3 fd = glm::normalize(glm::cross(du, dv));
    const glm::dvec3 n(varying3(s.tes.evaluate(glm::vec3(tc), s.patch, 0), kVaryingNormal));
    if (glm::dot(fd, n) < 0.0) fd = -fd;
    worst = std::max(worst, std::atan2(glm::length(glm::cross(fd, n)), glm::dot(fd, n)));
    bent = std::max(bent, std::acos(std::min(1.0, n.z)));
  }
  EXPECT_LT(worst, 2e-3) << "radians";
  EXPECT_GT(bent, 0.15) << "the normal must tilt (a f = 0.3)";
}

TEST(Displacement, BatchEqualsEvaluateOverPnAndFlat) {
  Lcg rng(11);
  for (int mode = 0; mode < 4; ++mode) {
    PnTcs pn_tcs;
    pn_tcs.normal_mode = PnNormalMode(mode);
    PnTes pn;
    pn.normal_mode = pn_tcs.normal_mode;
    pn.view_proj = glm::mat4(0.9f, 0.1f, 0.0f, 0.0f, -0.1f, 1.1f, 0.2f, 0.0f, 0.0f, 0.3f, 1.0f, 0.5f,
                             0.2f, -0.1f, 2.0f, 3.0f);
    PassThroughTcs flat_tcs;
    FlatTes flat;
    flat.tess_layout = TessLayout{TessDomain::Triangles, TessSpacing::Equal, TessWinding::Ccw, false};
    flat.view_proj = pn.view_proj;
    for (int k = 0; k < 2; ++k) {
      const TessEvalProgram& base = k == 0 ? static_cast<const TessEvalProgram&>(pn) : flat;
      DisplacedTes tes;
      tes.base = &base;
      tes.displacement = DisplacementSettings{true, 0.04f, 25.0f};
      tes.view_proj = pn.view_proj;
      const Patch in = make_patch({vertex(rng.vec(-1, 1), rng.vec(-1, 1)), vertex(rng.vec(-1, 1), rng.vec(-1, 1)),
                                   vertex(rng.vec(-1, 1), rng.vec(-1, 1))});
      const PatchOutput patch = k == 0 ? run_tcs(pn_tcs, in) : run_tcs(flat_tcs, in);
      TessEvalBatch batch;
      float coords[3][kTessEvalBatch];
      batch.count = 100;
      for (int i = 0; i < batch.count; ++i) {
        const float u = float(i % 10) / 9.0f, v = (1.0f - u) * float(i / 10) / 9.0f;
        coords[0][i] = u;
        coords[1][i] = v;
        coords[2][i] = 1.0f - u - v;
      }
      for (int c = 0; c < 3; ++c) batch.tess_coord[c] = coords[c];
      tes.evaluate_batch(patch, 0, batch);
      int mismatches = 0, moved = 0;
      for (int i = 0; i < batch.count; ++i) {
        const glm::vec3 tc(coords[0][i], coords[1][i], coords[2][i]);
        const ClipVertex one = tes.evaluate(tc, patch, 0), plain = base.evaluate(tc, patch, 0);
        for (int c = 0; c < 4; ++c) mismatches += test::bits(one.position[c]) != test::bits(batch.position[c][i]);
        for (int c = 0; c < kBuiltinVaryings; ++c)
          mismatches += test::bits(one.varyings[c]) != test::bits(batch.varyings[c][i]);
        moved += !same_bits(varying3(one, kVaryingPosition), varying3(plain, kVaryingPosition));
      }
      EXPECT_EQ(mismatches, 0) << "mode " << mode << " base " << k;
      EXPECT_GT(moved, 90) << "mode " << mode << " base " << k;
    }
  }
}

TEST(Displacement, SharedEdgesStayWatertight) {
  // Two PN patches on the edge p0-p1, listed in opposite directions: the displaced edge points
  // are the same bits from both (the base position and normal are, and so is what displace does
  // with them). Analytic normals differ across an edge, so they are left out.
  Lcg rng(5);
  for (int mode = 0; mode < 3; ++mode) {
    PnTcs tcs;
    tcs.normal_mode = PnNormalMode(mode);
    PnTes pn;
    pn.normal_mode = tcs.normal_mode;
    DisplacedTes tes;
    tes.base = &pn;
    tes.displacement = DisplacementSettings{true, -0.07f, 13.0f};
    for (int trial = 0; trial < 20; ++trial) {
      const StageVertex a = vertex(rng.vec(-1, 1), rng.vec(-1, 1)), b = vertex(rng.vec(-1, 1), rng.vec(-1, 1));
      const PatchOutput one = run_tcs(tcs, make_patch({a, b, vertex(rng.vec(-1, 1), rng.vec(-1, 1))}));
      const PatchOutput two = run_tcs(tcs, make_patch({b, a, vertex(rng.vec(-1, 1), rng.vec(-1, 1))}));
      for (int i = 0; i <= 16; ++i) {
        const float t = float(i) / 16.0f;
        const ClipVertex x = tes.evaluate({1.0f - t, t, 0.0f}, one, 0), y = tes.evaluate({t, 1.0f - t, 0.0f}, two, 1);
        EXPECT_TRUE(same_bits(varying3(x, kVaryingPosition), varying3(y, kVaryingPosition))) << mode << " " << i;
        EXPECT_TRUE(same_bits(varying3(x, kVaryingNormal), varying3(y, kVaryingNormal))) << mode << " " << i;
      }
    }
  }
}

std::string error_of(const std::vector<std::string>& sets) {
  try {
    load_scene("", sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(Displacement, SceneKeys) {
  const Scene off = load_scene("", {});
  EXPECT_FALSE(off.tessellation.displacement.enabled);
  const Scene on = load_scene("", {R"(tessellation.displacement={"amplitude": -0.03, "frequency": 30})"});
  EXPECT_TRUE(on.tessellation.displacement.enabled);
  EXPECT_EQ(on.tessellation.displacement.amplitude, -0.03f);
  EXPECT_EQ(on.tessellation.displacement.frequency, 30.0f);

  const std::string negative = error_of({R"(tessellation.displacement={"amplitude": 0.03, "frequency": -1})"});
  EXPECT_NE(negative.find("tessellation.displacement.frequency"), std::string::npos) << negative;
  EXPECT_NE(negative.find("must not be negative"), std::string::npos) << negative;
  const std::string nan = error_of({R"(tessellation.displacement={"amplitude": "nan", "frequency": 3})"});
  EXPECT_NE(nan.find("tessellation.displacement.amplitude"), std::string::npos) << nan;
  const std::string missing = error_of({R"(tessellation.displacement={"amplitude": 0.1})"});
  EXPECT_NE(missing.find("tessellation.displacement.frequency"), std::string::npos) << missing;
  const std::string unknown = error_of({R"(tessellation.displacement={"amplitude": 0.1, "frequency": 1, "phase": 2})"});
  EXPECT_NE(unknown.find("phase"), std::string::npos) << unknown;
  const std::string flat = error_of({R"(tessellation.displacement={"amplitude": 0.1, "frequency": 1})",
                                     "tessellation.enabled=false"});
  EXPECT_NE(flat.find("tessellation.displacement"), std::string::npos) << flat;
  EXPECT_NE(flat.find("tessellation.enabled"), std::string::npos) << flat;
}

}  // namespace
}  // namespace tessref
