// The executor: barrier phases, patch sizes, determinism across thread counts, shared edges.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <tuple>

#include "tess_test_util.h"

namespace tessref {
namespace {

using test::edge_points;
using test::Lcg;
using test::same_bits;
using test::same_bytes;
using test::tessellate_dump;
using test::vertex;

// Phase 0 writes gl_out[i].attr[0] = i + 1; phase 1 (after barrier()) sums every invocation's
// phase-0 value into gl_out[i].attr[1].x; phase 2 sums those. Running one invocation's phases
// back to back (no barrier) would give partial sums.
struct BarrierTcs : TessControlProgram {
  int n = 4;
  int output_vertices() const override { return n; }
  int phases() const override { return 3; }
  void run(int phase, int id, const Patch& in, PatchOutput& out) const override {
    auto& a = out.vertices[id].attr;
    if (phase == 0) {
      a[0] = glm::vec4(float(id + 1));
      if (id == 0) {
        out.levels.outer = {2, 2, 2, 2};
        out.levels.inner = {2, 2};
      }
    } else if (phase == 1) {
      for (int k = 0; k < n; ++k) a[1].x += out.vertices[k].attr[0].x;
    } else {
      for (int k = 0; k < n; ++k) a[1].y += out.vertices[k].attr[1].x;
    }
  }
};

// Reports what reached gl_in[] of the TES: the count and a checksum of every vertex's attr[2].
struct ProbeTes : TessEvalProgram {
  TessLayout layout() const override { return TessLayout{}; }
  int num_varyings() const override { return 9; }
  ClipVertex evaluate(const glm::vec3& tc, const PatchOutput& patch, int prim) const override {
    ClipVertex v;
    v.position = glm::vec4(tc, 1.0f);
    float sum = 0.0f;
    for (int k = 0; k < patch.vertex_count; ++k) sum += patch.vertices[k].attr[2].x * float(k + 1);
    v.varyings[6] = float(patch.vertex_count);
    v.varyings[7] = sum;
    v.varyings[8] = float(prim);
    v.varyings[0] = patch.vertices[0].attr[1].x;
    v.varyings[1] = patch.vertices[0].attr[1].y;
    return v;
  }
};

TEST(TessExecutor, BarrierPhasesSeeOtherInvocationsOutputs) {
  std::vector<StageVertex> vs(4);
  BarrierTcs tcs;
  ProbeTes tes;
  TriangleBatch out;
  const TessDrawInput input{vs, {}, 4};
  const TessStats st = tessellate(input, 0, 1, tcs, tes, TessOptions{}, Parallel(1), out);
  ASSERT_EQ(st.patches_in, 1u);
  ASSERT_GT(out.vertices.size(), 0u);
  for (const ClipVertex& v : out.vertices) {
    EXPECT_EQ(v.varyings[0], 10.0f);  // 1 + 2 + 3 + 4
    EXPECT_EQ(v.varyings[1], 40.0f);  // 4 * 10
  }
}

TEST(TessExecutor, PatchSizesOtherThanThreePassThrough) {
  for (int pv : {1, 4, 16, 32}) {
    // Two patches drawn through an index buffer that reverses the vertex order.
    std::vector<StageVertex> vs(2 * pv);
    for (int i = 0; i < 2 * pv; ++i) vs[i].attr[2].x = float(i);
    std::vector<std::uint32_t> idx(2 * pv);
    for (int i = 0; i < 2 * pv; ++i) idx[i] = std::uint32_t(2 * pv - 1 - i);
    PassThroughTcs tcs;
    tcs.vertices = pv;
    tcs.levels = TessLevelSettings::uniform(1.0f, 1.0f);
    ProbeTes tes;
    TriangleBatch out;
    const TessStats st = tessellate(TessDrawInput{vs, idx, pv}, 0, 2, tcs, tes, TessOptions{},
                                    Parallel(2), out);
    EXPECT_EQ(st.patches_in, 2u);
    ASSERT_EQ(out.num_varyings, 9);
    ASSERT_FALSE(out.vertices.empty());
    for (const ClipVertex& v : out.vertices) {
      ASSERT_EQ(v.varyings[6], float(pv));
      const int p = int(v.varyings[8]);
      float expect = 0.0f;
      for (int k = 0; k < pv; ++k) expect += float(2 * pv - 1 - (p * pv + k)) * float(k + 1);
      EXPECT_EQ(v.varyings[7], expect) << "patch vertices " << pv << " patch " << p;
    }
    EXPECT_EQ(int(out.vertices.front().varyings[8]), 0);
    EXPECT_EQ(int(out.vertices.back().varyings[8]), 1);
  }
}

TEST(TessExecutor, QuadPatchOfFourInterpolatesItsCorners) {
  const std::vector<StageVertex> vs = {vertex({0, 0, 0}, {0, 0, 1}), vertex({2, 0, 0}, {0, 0, 1}),
                                       vertex({2, 1, 0}, {0, 0, 1}), vertex({0, 1, 0}, {0, 0, 1})};
  PassThroughTcs tcs;
  tcs.vertices = 4;
  tcs.levels = TessLevelSettings::uniform(3.0f, 3.0f);
  FlatTes tes;
  tes.tess_layout.domain = TessDomain::Quads;
  std::vector<TessDumpRecord> dump;
  TessOptions opt;
  opt.dump = &dump;
  TriangleBatch out;
  tessellate(TessDrawInput{vs, {}, 4}, 0, 1, tcs, tes, opt, Parallel(1), out);
  ASSERT_FALSE(dump.empty());
  for (const auto& r : dump) {
    EXPECT_EQ(r.position, glm::vec3(2.0f * r.tess_coord.x, r.tess_coord.y, 0.0f));
    EXPECT_EQ(r.normal, glm::vec3(0, 0, 1));
  }
}

TEST(TessExecutor, RejectsBadSizesAndDropsBadIndices) {
  std::vector<StageVertex> vs(3);
  PassThroughTcs tcs;
  FlatTes tes;
  TriangleBatch out;
  EXPECT_THROW(tessellate(TessDrawInput{vs, {}, 0}, 0, 1, tcs, tes, {}, Parallel(1), out),
               std::invalid_argument);
  EXPECT_THROW(tessellate(TessDrawInput{vs, {}, 33}, 0, 1, tcs, tes, {}, Parallel(1), out),
               std::invalid_argument);
  tcs.vertices = 0;
  EXPECT_THROW(tessellate(TessDrawInput{vs, {}, 3}, 0, 1, tcs, tes, {}, Parallel(1), out),
               std::invalid_argument);
  tcs.vertices = 3;
  const std::vector<std::uint32_t> idx = {0, 1, 7, 0, 1, 2};
  const TessStats st = tessellate(TessDrawInput{vs, idx, 3}, 0, 2, tcs, tes, {}, Parallel(1), out);
  EXPECT_EQ(st.patches_in, 2u);
  EXPECT_EQ(st.patches_invalid, 1u);
  EXPECT_GT(st.triangles_out, 0u);
}

TEST(TessExecutor, NaNAndZeroLevelsDiscard) {
  std::vector<StageVertex> vs = {vertex({0, 0, 0}, {0, 0, 1}), vertex({1, 0, 0}, {0, 0, 1}),
                                 vertex({0, 1, 0}, {0, 0, 1})};
  for (float level : {std::nanf(""), 0.0f, -1.0f}) {
    PnTcs tcs;
    tcs.levels = TessLevelSettings::uniform(level, level);
    PnTes tes;
    TriangleBatch out;
    const TessStats st = tessellate(TessDrawInput{vs, {}, 3}, 0, 1, tcs, tes, {}, Parallel(1), out);
    EXPECT_EQ(st.patches_discarded, 1u);
    EXPECT_TRUE(out.vertices.empty());
  }
}

// A closed, curved mesh: an octahedron with vertex normals pointing out from the centre.
void octahedron(int subdivisions, std::vector<StageVertex>& vs, std::vector<std::uint32_t>& idx) {
  std::vector<glm::vec3> p = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<glm::uvec3> tris = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                  {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<unsigned, unsigned>, unsigned> mid;
    auto m = [&](unsigned a, unsigned b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      p.push_back(glm::normalize(p[a] + p[b]));
      return mid[key] = unsigned(p.size() - 1);
    };
    std::vector<glm::uvec3> next;
    for (auto t : tris) {
      const unsigned a = m(t.x, t.y), b = m(t.y, t.z), c = m(t.z, t.x);
      next.insert(next.end(), {{t.x, a, c}, {a, t.y, b}, {c, b, t.z}, {a, b, c}});
    }
    tris = next;
  }
  vs.clear();
  for (const auto& q : p) vs.push_back(vertex(q * 2.0f, glm::normalize(q)));
  idx.clear();
  for (auto t : tris) idx.insert(idx.end(), {t.x, t.y, t.z});
}

TEST(TessExecutor, OutputDoesNotDependOnThreadsOrGrain) {
  std::vector<StageVertex> vs;
  std::vector<std::uint32_t> idx;
  octahedron(2, vs, idx);
  const TessDrawInput input{vs, idx, 3};
  PnTcs tcs;
  tcs.levels = TessLevelSettings::uniform(5.3f, 4.6f);
  PnTes tes;
  tes.view_proj = glm::mat4(0.5f);
  TriangleBatch ref;
  std::vector<TessDumpRecord> ref_dump;
  TessOptions opt;
  opt.dump = &ref_dump;
  opt.patches_per_task = 32;
  const TessStats ref_stats = tessellate(input, 0, input.patch_count(), tcs, tes, opt, Parallel(1), ref);
  ASSERT_EQ(ref_stats.patches_in, 128u);
  ASSERT_GT(ref.triangle_count(), 128u);
  EXPECT_EQ(ref_stats.triangles_out, ref.triangle_count());
  for (int threads : {1, 2, 8})
    for (std::size_t grain : {1u, 7u, 64u, 1000u}) {
      TriangleBatch out;
      std::vector<TessDumpRecord> dump;
      opt.dump = &dump;
      opt.patches_per_task = grain;
      const TessStats st =
          tessellate(input, 0, input.patch_count(), tcs, tes, opt, Parallel(threads), out);
      EXPECT_TRUE(same_bytes(out, ref)) << threads << " threads, grain " << grain;
      ASSERT_EQ(dump.size(), ref_dump.size());
      EXPECT_EQ(std::memcmp(dump.data(), ref_dump.data(), dump.size() * sizeof(TessDumpRecord)), 0);
      EXPECT_EQ(st.domain_points, ref_stats.domain_points);
      EXPECT_EQ(st.triangles_out, ref_stats.triangles_out);
    }
  // Chunked draws concatenate to the same batch.
  TriangleBatch joined;
  std::size_t chunks = 0;
  opt.dump = nullptr;
  tessellate_chunks(input, 10, tcs, tes, opt, Parallel(2), [&](const TriangleBatch& b) {
    ++chunks;
    append_triangles(joined, b);
  });
  EXPECT_EQ(chunks, 13u);
  EXPECT_TRUE(same_bytes(joined, ref));
}

TEST(TessExecutor, SharedEdgeIsBitIdenticalInBothPatches) {
  // Patch 0 = (A, B, C), patch 1 = (B, A, D): the edge A-B runs in opposite directions and sits in
  // different slots; the extra patches rotate patch 1 through every slot placement.
  Lcg rng(7);
  for (int trial = 0; trial < 6; ++trial) {
    const glm::vec3 A = rng.vec(-1, 1), B = rng.vec(-1, 1), C = rng.vec(-1, 1), D = rng.vec(-1, 1);
    auto nrm = [&](const glm::vec3&) { return glm::normalize(rng.vec(-1, 1) + glm::vec3(0, 0, 2)); };
    const glm::vec3 nA = nrm(A), nB = nrm(B), nC = nrm(C), nD = nrm(D);
    const std::vector<StageVertex> vs = {vertex(A, nA), vertex(B, nB), vertex(C, nC), vertex(D, nD)};
    // Opposite corner index of the shared edge in each patch: 2, 2, 0, 1.
    const std::vector<std::uint32_t> idx = {0, 1, 2, 1, 0, 3, 3, 1, 0, 0, 3, 1};
    const int opposite[4] = {2, 2, 0, 1};
    for (TessSpacing spacing : {TessSpacing::Equal, TessSpacing::FractionalOdd, TessSpacing::FractionalEven})
      for (float level : {1.0f, 2.0f, 3.7f, 5.2f, 8.0f, 13.49f, -1.0f /* adaptive */})
        for (PnNormalMode mode : {PnNormalMode::Linear, PnNormalMode::Quadratic,
                                  PnNormalMode::QuadraticCorrected, PnNormalMode::Analytic}) {
          PnTcs tcs;
          tcs.normal_mode = mode;
          tcs.levels = TessLevelSettings::uniform(level, level + 1.0f);
          if (level < 0.0f) {
            // Screen-space levels: every edge its own level, shared edges agreeing.
            tcs.levels.adaptive = true;
            tcs.levels.screen.pixels_per_segment = 9.0f + float(trial);
            tcs.levels.screen.viewport_pixels = {400, 300};
          }
          PnTes tes;
          tes.normal_mode = mode;
          tes.spacing = spacing;
          const auto dump = tessellate_dump(TessDrawInput{vs, idx, 3}, 4, tcs, tes);
          const auto ref = edge_points(dump, 0, opposite[0]);
          ASSERT_GE(ref.size(), 2u);
          for (std::uint32_t p = 1; p < 4; ++p) {
            const auto other = edge_points(dump, p, opposite[p]);
            ASSERT_EQ(other.size(), ref.size()) << to_string(spacing) << " " << level;
            for (std::size_t i = 0; i < ref.size(); ++i) {
              EXPECT_TRUE(same_bits(std::get<0>(other[i]), std::get<0>(ref[i])))
                  << to_string(spacing) << " level " << level << " " << to_string(mode)
                  << " patch " << p << " point " << i;
              // Analytic normals depend on the cross-edge derivative: C0 patches differ there.
              if (mode != PnNormalMode::Analytic) {
                EXPECT_TRUE(same_bits(std::get<1>(other[i]), std::get<1>(ref[i])))
                    << to_string(mode) << " patch " << p;
              }
            }
          }
        }
  }
}

TEST(TessExecutor, GarbageInputDoesNotCrash) {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::nanf("");
  const std::vector<StageVertex> vs = {
      vertex({0, 0, 0}, {0, 0, 1}), vertex({inf, 0, 0}, {0, 0, 1}), vertex({0, nan, 0}, {nan, 0, 1}),
      vertex({1e30f, -1e30f, 0}, {1e30f, 0, 0}), vertex({0, 0, 0}, {0, 0, 0}), vertex({1, 1, 1}, {inf, inf, inf})};
  std::vector<std::uint32_t> idx;
  for (std::uint32_t a = 0; a < 6; ++a)
    for (std::uint32_t b = 0; b < 6; ++b) idx.insert(idx.end(), {a, b, (a + b + 1) % 6});
  for (PnNormalMode mode : {PnNormalMode::Linear, PnNormalMode::Quadratic,
                            PnNormalMode::QuadraticCorrected, PnNormalMode::Analytic})
    for (bool adaptive : {false, true})
      for (float level : {1e30f, inf, nan, 3.0f}) {
        PnTcs tcs;
        tcs.normal_mode = mode;
        tcs.levels = TessLevelSettings::uniform(level, level);
        tcs.levels.adaptive = adaptive;
        PnTes tes;
        tes.normal_mode = mode;
        TriangleBatch out;
        const TessStats st = tessellate(TessDrawInput{vs, idx, 3}, 0, idx.size() / 3, tcs, tes, {},
                                        Parallel(2), out);
        EXPECT_EQ(st.patches_in, idx.size() / 3);
        EXPECT_EQ(st.triangles_out, out.triangle_count());
      }
}

TEST(TessExecutor, PointModeAndIsolinesGoToTheirOwnLists) {
  const std::vector<StageVertex> vs = {vertex({0, 0, 0}, {0, 0, 1}), vertex({1, 0, 0}, {0, 0, 1}),
                                       vertex({0, 1, 0}, {0, 0, 1}), vertex({1, 1, 0}, {0, 0, 1})};
  PnTcs tcs;
  tcs.levels = TessLevelSettings::uniform(4.0f, 4.0f);
  PnTes tes;
  tes.point_mode = true;
  std::vector<ClipVertex> points, lines;
  TessOptions opt;
  opt.points = &points;
  TriangleBatch out;
  TessStats st = tessellate(TessDrawInput{vs, {}, 3}, 0, 1, tcs, tes, opt, Parallel(1), out);
  EXPECT_TRUE(out.vertices.empty());
  EXPECT_EQ(st.points_out, st.domain_points);
  EXPECT_EQ(points.size(), st.domain_points);

  PassThroughTcs lines_tcs;
  lines_tcs.vertices = 4;
  lines_tcs.levels = TessLevelSettings::uniform(3.0f, 1.0f);  // 3 lines of 3 segments
  FlatTes lines_tes;
  lines_tes.tess_layout.domain = TessDomain::Isolines;
  opt.points = nullptr;
  opt.lines = &lines;
  st = tessellate(TessDrawInput{vs, {}, 4}, 0, 1, lines_tcs, lines_tes, opt, Parallel(1), out);
  EXPECT_TRUE(out.vertices.empty());
  EXPECT_EQ(st.lines_out, 9u);
  EXPECT_EQ(lines.size(), 18u);
}

TEST(TessExecutor, WindingFollowsTheLayoutWithGlCornerMapping) {
  // gl_TessCoord.x weighs gl_in[0]: a CCW patch in the xy plane must give CCW triangles for
  // layout(ccw) and CW ones for layout(cw) (GL 4.6 section 11.2.2.1).
  const std::vector<StageVertex> vs = {vertex({0, 0, 0}, {0, 0, 1}), vertex({1, 0, 0}, {0, 0, 1}),
                                       vertex({0.2f, 1, 0}, {0, 0, 1})};
  for (TessWinding winding : {TessWinding::Ccw, TessWinding::Cw})
    for (TessSpacing spacing : {TessSpacing::Equal, TessSpacing::FractionalOdd}) {
      PnTcs tcs;
      tcs.levels = TessLevelSettings::uniform(4.5f, 3.0f);
      PnTes tes;
      tes.winding = winding;
      tes.spacing = spacing;
      TriangleBatch out;
      tessellate(TessDrawInput{vs, {}, 3}, 0, 1, tcs, tes, {}, Parallel(1), out);
      ASSERT_GT(out.triangle_count(), 1u);
      for (std::size_t t = 0; t < out.triangle_count(); ++t) {
        const glm::vec2 a(out.corner(t, 0).position), b(out.corner(t, 1).position),
            c(out.corner(t, 2).position);
        const float area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        if (winding == TessWinding::Ccw)
          EXPECT_GT(area, 0.0f) << t;
        else
          EXPECT_LT(area, 0.0f) << t;
      }
    }
}

TEST(TessExecutor, FlatSharedEdgeIsBitIdentical) {
  const std::vector<StageVertex> vs = {vertex({0.1f, 0.3f, 0.7f}, {0, 0, 1}),
                                       vertex({0.9f, -0.2f, 0.3f}, {0, 1, 1}),
                                       vertex({0.3f, 0.8f, 0.1f}, {1, 0, 1}),
                                       vertex({0.7f, -0.9f, -0.4f}, {1, 1, 1})};
  const std::vector<std::uint32_t> idx = {0, 1, 2, 1, 0, 3};
  for (TessSpacing spacing : {TessSpacing::Equal, TessSpacing::FractionalOdd, TessSpacing::FractionalEven}) {
    PassThroughTcs tcs;
    tcs.levels = TessLevelSettings::uniform(6.3f, 6.3f);
    FlatTes tes;
    tes.tess_layout.spacing = spacing;
    std::vector<TessDumpRecord> dump;
    TessOptions opt;
    opt.dump = &dump;
    TriangleBatch out;
    tessellate(TessDrawInput{vs, idx, 3}, 0, 2, tcs, tes, opt, Parallel(1), out);
    const auto a = edge_points(dump, 0, 2), b = edge_points(dump, 1, 2);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_TRUE(same_bits(std::get<0>(a[i]), std::get<0>(b[i])));
      EXPECT_TRUE(same_bits(std::get<1>(a[i]), std::get<1>(b[i])));
    }
  }
}

TEST(TessExecutor, FlatQuadSharedEdgeIsBitIdentical) {
  // Quad A = (0, 1, 2, 3) has the shared edge 1-2 at u = 1; quad B = (2, 1, 4, 5) has it at v = 0,
  // running the other way.
  const std::vector<StageVertex> vs = {
      vertex({0.1f, 0.3f, 0.7f}, {0, 0, 1}), vertex({0.9f, -0.2f, 0.3f}, {0, 1, 1}),
      vertex({1.3f, 0.8f, 0.1f}, {1, 0, 1}), vertex({0.2f, 0.9f, -0.4f}, {1, 1, 1}),
      vertex({2.1f, 0.7f, 0.3f}, {0, 0, 1}), vertex({1.9f, -0.3f, 0.5f}, {0, 1, 0})};
  const std::vector<std::uint32_t> idx = {0, 1, 2, 3, 2, 1, 4, 5};
  for (TessSpacing spacing : {TessSpacing::Equal, TessSpacing::FractionalOdd, TessSpacing::FractionalEven}) {
    PassThroughTcs tcs;
    tcs.vertices = 4;
    tcs.levels = TessLevelSettings::uniform(5.7f, 3.2f);
    FlatTes tes;
    tes.tess_layout.domain = TessDomain::Quads;
    tes.tess_layout.spacing = spacing;
    std::vector<TessDumpRecord> dump;
    TessOptions opt;
    opt.dump = &dump;
    TriangleBatch out;
    tessellate(TessDrawInput{vs, idx, 4}, 0, 2, tcs, tes, opt, Parallel(1), out);
    std::vector<std::tuple<glm::vec3, glm::vec3>> a, b;
    for (const auto& r : dump) {
      if (r.patch_id == 0 && r.tess_coord.x == 1.0f) a.emplace_back(r.position, r.normal);
      if (r.patch_id == 1 && r.tess_coord.y == 0.0f) b.emplace_back(r.position, r.normal);
    }
    auto by_position = [](const auto& x, const auto& y) {
      const glm::vec3 &p = std::get<0>(x), &q = std::get<0>(y);
      return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z);
    };
    std::sort(a.begin(), a.end(), by_position);
    std::sort(b.begin(), b.end(), by_position);
    ASSERT_EQ(a.size(), b.size());
    ASSERT_GE(a.size(), 6u);
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_TRUE(same_bits(std::get<0>(a[i]), std::get<0>(b[i]))) << to_string(spacing) << " " << i;
      EXPECT_TRUE(same_bits(std::get<1>(a[i]), std::get<1>(b[i]))) << to_string(spacing) << " " << i;
    }
  }
}

TEST(TessExecutor, FlatPnPatchThroughTheExecutorStaysOnItsPlane) {
  const glm::vec3 p0(0.2f, -0.1f, 0.3f), p1(1.1f, 0.2f, -0.4f), p2(0.1f, 0.9f, 0.5f);
  const glm::vec3 face = glm::normalize(glm::cross(p1 - p0, p2 - p0));
  const std::vector<StageVertex> vs = {vertex(p0, face), vertex(p1, face), vertex(p2, face)};
  PnTcs tcs;
  tcs.levels = TessLevelSettings::uniform(7.0f, 7.0f);
  PnTes tes;
  std::vector<TessDumpRecord> dump;
  TessOptions opt;
  opt.dump = &dump;
  TriangleBatch out;
  const TessStats st = tessellate(TessDrawInput{vs, {}, 3}, 0, 1, tcs, tes, opt, Parallel(1), out);
  EXPECT_EQ(st.domain_points, dump.size());
  for (const auto& r : dump) {
    EXPECT_LE(std::abs(glm::dot(r.position - p0, face)), 1e-6f);
    EXPECT_LE(glm::length(r.normal - face), 1e-6f);
  }
  // Every emitted vertex is one of the evaluated points, and gl_Position = view_proj * position.
  for (const auto& v : out.vertices)
    EXPECT_EQ(v.position, glm::vec4(v.varyings[0], v.varyings[1], v.varyings[2], 1.0f));
}

}  // namespace
}  // namespace tessref
