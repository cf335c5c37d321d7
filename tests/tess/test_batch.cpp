// The batched stage interface: batch kernels against the per-invocation programs they replace,
// bit for bit, on both SIMD paths; the pattern cache; the TCS phase entry point.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <thread>

#include "common/simd.h"
#include "stages/programs/normals.h"
#include "stages/programs/phong.h"
#include "stages/schemes/pn_batch.h"
#include "tess_test_util.h"

namespace tessref {
namespace {

using test::Lcg;
using test::make_patch;
using test::run_tcs;
using test::vertex;

// Restores the SIMD path chosen at start-up when a test ends.
struct SimdPathGuard {
  SimdPath saved = simd_path();
  ~SimdPathGuard() { set_simd_path(saved); }
};

std::vector<SimdPath> paths() {
  std::vector<SimdPath> p{SimdPath::Scalar};
  if (cpu_has_avx2()) p.push_back(SimdPath::Avx2);
  return p;
}

// Random PN patches with the inputs that take the kernel's other branches: zero, tiny and huge
// normals, repeated corners (zero-length edges), coordinates of mixed magnitude.
std::vector<StageVertex> random_corners(Lcg& rng, int kind) {
  std::vector<StageVertex> vs;
  for (int i = 0; i < 3; ++i) {
    glm::vec3 p = rng.vec(-2.0f, 2.0f), n = rng.vec(-1.0f, 1.0f);
    if (kind == 1 && i == 1) n = glm::vec3(0.0f);
    if (kind == 2) n *= 1e-20f;
    if (kind == 3 && i == 2) p = glm::vec3(vs[0].attr[kAttrPosition]);
    if (kind == 4) p *= 1e6f;
    vs.push_back(vertex(p, n));
  }
  return vs;
}

// Points of a batch: random barycentric triples plus corners and edge points.
void fill_coords(Lcg& rng, int count, std::vector<float> (&coord)[3]) {
  for (auto& c : coord) c.resize(count);
  for (int i = 0; i < count; ++i) {
    float u = rng.uniform(0.0f, 1.0f), v = rng.uniform(0.0f, 1.0f);
    if (u + v > 1.0f) u = 1.0f - u, v = 1.0f - v;
    if (i % 7 == 0) v = 0.0f;
    if (i % 11 == 0) u = 1.0f, v = 0.0f;
    coord[0][i] = u;
    coord[1][i] = v;
    coord[2][i] = 1.0f - u - v;
  }
}

TEST(TessBatch, PnEvaluateBatchEqualsEvaluateOnBothSimdPaths) {
  SimdPathGuard guard;
  Lcg rng(71);
  std::size_t compared = 0;
  for (SimdPath path : paths()) {
    set_simd_path(path);
    for (PnNormalMode mode : {PnNormalMode::Linear, PnNormalMode::Quadratic,
                              PnNormalMode::QuadraticCorrected, PnNormalMode::Analytic}) {
      for (int trial = 0; trial < 200; ++trial) {
        PnTcs tcs;
        tcs.normal_mode = mode;
        const PatchOutput net = run_tcs(tcs, make_patch(random_corners(rng, trial % 5)));
        PnTes tes;
        tes.normal_mode = mode;
        tes.view_proj = glm::mat4(glm::vec4(0.9f, 0.1f, 0.0f, 0.01f), glm::vec4(-0.2f, 1.1f, 0.3f, 0.0f),
                                  glm::vec4(0.05f, 0.0f, -1.0f, -1.0f), glm::vec4(0.3f, -0.1f, 4.0f, 5.0f));
        const int count = 1 + trial % kTessEvalBatch;
        std::vector<float> coord[3];
        fill_coords(rng, count, coord);
        TessEvalBatch batch;
        batch.count = count;
        for (int c = 0; c < 3; ++c) batch.tess_coord[c] = coord[c].data();
        tes.evaluate_batch(net, 0, batch);
        for (int i = 0; i < count; ++i) {
          const ClipVertex ref =
              tes.evaluate(glm::vec3(coord[0][i], coord[1][i], coord[2][i]), net, 0);
          for (int c = 0; c < 4; ++c)
            ASSERT_EQ(test::bits(batch.position[c][i]), test::bits(ref.position[c]))
                << to_string(path) << " " << to_string(mode) << " trial " << trial << " point " << i;
          for (int k = 0; k < kBuiltinVaryings; ++k)
            ASSERT_EQ(test::bits(batch.varyings[k][i]), test::bits(ref.varyings[k]))
                << to_string(path) << " " << to_string(mode) << " trial " << trial << " point " << i
                << " varying " << k;
          ++compared;
        }
      }
    }
  }
  EXPECT_GE(compared, 4u * 200u * 16u);
}

TEST(TessBatch, ScalarAndAvx2KernelsAgreeBitForBit) {
  if (!cpu_has_avx2()) GTEST_SKIP() << "no AVX2 on this CPU: only the scalar kernel runs";
  Lcg rng(5);
  for (int trial = 0; trial < 500; ++trial) {
    PnBatchPatch k{};
    float* fields = &k.p[0][0];
    for (std::size_t i = 0; i < offsetof(PnBatchPatch, view_proj) / sizeof(float) + 16; ++i)
      fields[i] = rng.uniform(-3.0f, 3.0f);
    if (trial % 3 == 0) std::memset(k.n, 0, sizeof k.n), std::memset(k.mid, 0, sizeof k.mid);
    k.quadratic = trial % 2;
    std::vector<float> coord[3];
    fill_coords(rng, kTessEvalBatch, coord);
    float out_s[10][kTessEvalBatch], out_v[10][kTessEvalBatch];
    float* cs[4] = {out_s[0], out_s[1], out_s[2], out_s[3]};
    float* vs[6] = {out_s[4], out_s[5], out_s[6], out_s[7], out_s[8], out_s[9]};
    float* cv[4] = {out_v[0], out_v[1], out_v[2], out_v[3]};
    float* vv[6] = {out_v[4], out_v[5], out_v[6], out_v[7], out_v[8], out_v[9]};
    pn_batch_scalar(k, kTessEvalBatch, coord[0].data(), coord[1].data(), coord[2].data(), cs, vs);
    pn_batch_avx2(k, kTessEvalBatch, coord[0].data(), coord[1].data(), coord[2].data(), cv, vv);
    ASSERT_EQ(std::memcmp(out_s, out_v, sizeof out_s), 0) << "trial " << trial;
  }
}

// Same bits, or both NaN: a zero normal normalizes to NaN (as in GLSL), and which NaN comes out of
// an operation on two NaNs depends on the operand order the compiler picks.
bool same_or_both_nan(float a, float b) {
  return test::bits(a) == test::bits(b) || (std::isnan(a) && std::isnan(b));
}

// Built-in fragment programs: shade_batch must give shade()'s bits for every live lane.
template <class Program>
void check_shading_batch(const Program& fs) {
  SimdPathGuard guard;
  Lcg rng(13);
  for (SimdPath path : paths()) {
    set_simd_path(path);
    for (int trial = 0; trial < 100; ++trial) {
      FragmentBatch batch{};
      batch.quads = 1 + trial % kFragmentQuads;
      batch.num_varyings = kBuiltinVaryings;
      for (int l = 0; l < batch.lanes(); ++l) {
        batch.live[l] = (l + trial) % 5 != 0;
        batch.front_facing[l] = l % 2;
        for (int c = 0; c < 4; ++c) batch.frag_coord[c][l] = rng.uniform(0.0f, 100.0f);
        for (int k = 0; k < kBuiltinVaryings; ++k) batch.varyings[k][l] = rng.uniform(-2.0f, 2.0f);
        if (l % 9 == 0)  // a zero normal (NaN after normalize, as in GLSL)
          for (int k = 0; k < 3; ++k) batch.varyings[kVaryingNormal + k][l] = 0.0f;
      }
      FragmentBatch ref = batch;
      fs.FragmentProgram::shade_batch(ref);  // the per-lane default: shade()
      fs.shade_batch(batch);
      for (int l = 0; l < batch.lanes(); ++l) {
        if (!batch.live[l]) continue;
        for (int c = 0; c < 4; ++c) {
          ASSERT_TRUE(same_or_both_nan(batch.color[c][l], ref.color[c][l]))
              << to_string(path) << " trial " << trial << " lane " << l << " color " << c;
          ASSERT_TRUE(same_or_both_nan(batch.aux[c][l], ref.aux[c][l]))
              << to_string(path) << " trial " << trial << " lane " << l << " aux " << c;
        }
      }
    }
  }
}

TEST(TessBatch, PhongShadeBatchEqualsShade) {
  programs::PhongShader fs;
  fs.u_eye = glm::vec3(0.5f, 3.0f, 7.0f);
  fs.u_num_lights = 3;
  fs.u_light_position = {glm::vec3(-2, 5, 10), glm::vec3(4, -1, 2), glm::vec3(0, 0, 0.5f)};
  fs.u_light_intensity = {glm::vec3(1.0f), glm::vec3(0.3f, 0.2f, 0.9f), glm::vec3(0.5f)};
  fs.u_ka = 0.1f;
  fs.u_kd = 0.6f;
  fs.u_ks = 0.4f;
  fs.u_shininess = 27.0f;
  fs.u_color = glm::vec3(0.8f, 0.5f, 0.2f);
  check_shading_batch(fs);
}

TEST(TessBatch, NormalsShadeBatchEqualsShade) { check_shading_batch(programs::NormalsShader{}); }

TEST(TessPatternCache, GivesTheGeneratorsPatternAndCountsHits) {
  TessPatternCache cache;
  const TessLayout layout{TessDomain::Triangles, TessSpacing::FractionalOdd, TessWinding::Ccw, false};
  TessLevels levels;
  levels.outer = {5.5f, 3.0f, 7.25f, 1.0f};
  levels.inner = {4.0f, 1.0f};
  const auto a = cache.get(layout, levels, TessProfile::llvmpipe());
  const auto b = cache.get(layout, levels, TessProfile::llvmpipe());
  EXPECT_EQ(a.get(), b.get());
  const TessDomainPoints ref = generate_tessellation(layout, levels);
  ASSERT_EQ(a->points.coords.size(), ref.coords.size());
  EXPECT_EQ(std::memcmp(a->points.coords.data(), ref.coords.data(), ref.coords.size() * sizeof(glm::vec3)), 0);
  EXPECT_EQ(a->points.indices, ref.indices);
  for (std::size_t i = 0; i < ref.coords.size(); ++i)
    for (int c = 0; c < 3; ++c) ASSERT_EQ(test::bits(a->coord[c][i]), test::bits(ref.coords[i][c]));
  EXPECT_EQ(a->coord[0].size() % kPatternPadding, 0u);
  // Another profile, another key: the spec-literal profile differs only near level 1.
  const auto c = cache.get(layout, levels, TessProfile::spec_literal());
  EXPECT_NE(a.get(), c.get());
  // -0 and +0, or two NaNs, are different keys but give what the generator gives for each.
  TessLevels nan_levels = levels;
  nan_levels.outer[0] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_TRUE(cache.get(layout, nan_levels, TessProfile::llvmpipe())->points.discarded);
  const TessPatternCache::Stats st = cache.stats();
  EXPECT_EQ(st.hits, 1u);
  EXPECT_EQ(st.misses, 3u);
  EXPECT_EQ(st.entries, 3u);
}

TEST(TessPatternCache, StaysWithinItsBoundAndKeepsPatternsInUse) {
  // Room for about two level-64 patterns: the third empties the cache first.
  const TessLayout layout{TessDomain::Triangles, TessSpacing::Equal, TessWinding::Ccw, false};
  const std::size_t one = make_pattern(layout, TessLevels{{64, 64, 64, 1}, {64, 1}},
                                       TessProfile::llvmpipe())->bytes();
  TessPatternCache cache(2 * one + one / 2);
  std::vector<std::shared_ptr<const TessPattern>> held;
  for (float level : {64.0f, 63.0f, 62.0f, 61.0f}) {
    held.push_back(cache.get(layout, TessLevels{{level, level, level, 1}, {level, 1}},
                             TessProfile::llvmpipe()));
    EXPECT_LE(cache.stats().bytes, 2 * one + one / 2);
  }
  EXPECT_GE(cache.stats().clears, 1u);
  // The first pattern is still whole after the clear emptied the cache under it.
  EXPECT_EQ(held.front()->points.coords.size(),
            generate_tessellation(layout, TessLevels{{64, 64, 64, 1}, {64, 1}}).coords.size());
}

TEST(TessPatternCache, ConcurrentLookupsAgree) {
  TessPatternCache cache;
  const TessLayout layout{TessDomain::Quads, TessSpacing::FractionalEven, TessWinding::Cw, false};
  std::vector<const TessPattern*> seen(8 * 50);
  std::vector<std::thread> threads;
  for (int t = 0; t < 8; ++t)
    threads.emplace_back([&, t] {
      for (int i = 0; i < 50; ++i) {
        const float level = 2.0f + float(i % 10);
        seen[t * 50 + i] = cache.get(layout, TessLevels{{level, 3, 4, 5}, {level, 2}},
                                     TessProfile::llvmpipe()).get();
      }
    });
  for (auto& th : threads) th.join();
  // One pattern per level set, whichever thread made it first.
  for (int t = 0; t < 8; ++t)
    for (int i = 0; i < 50; ++i) EXPECT_EQ(seen[t * 50 + i], seen[i % 10]);
  EXPECT_EQ(cache.stats().entries, 10u);
}

// A program that counts phases through the batched entry point.
struct PhaseProbeTcs : TessControlProgram {
  int output_vertices() const override { return 3; }
  int phases() const override { return 2; }
  void run(int phase, int id, const Patch&, PatchOutput& out) const override {
    out.vertices[id].attr[0][phase] += 1.0f;
    out.levels.outer = {2, 2, 2, 1};
    out.levels.inner = {2, 1};
  }
};

TEST(TessBatch, RunPhaseRunsEveryInvocationOfThePhase) {
  PhaseProbeTcs tcs;
  Patch in;
  PatchOutput out;
  tcs.run_phase(0, in, out);
  tcs.run_phase(1, in, out);
  for (int id = 0; id < 3; ++id) {
    EXPECT_EQ(out.vertices[id].attr[0].x, 1.0f);
    EXPECT_EQ(out.vertices[id].attr[0].y, 1.0f);
  }
}

}  // namespace
}  // namespace tessref
