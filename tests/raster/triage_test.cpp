// The triage before setup (raster/triage.h): each verdict is what setup_triangle concludes for the
// same triangle, and the plain and AVX2 kernels give the same verdicts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "common/simd.h"
#include "raster/setup.h"
#include "raster/triage.h"
#include "raster_test_util.h"

namespace tessref {
namespace {

using raster::Triage;

constexpr int kWidth = 64, kHeight = 48;

// Triangles of every size the triage meets: most below a pixel (a fine tessellation), some of a
// few pixels, some large, some reaching past the viewport (clipped: left to setup), some with
// corners on pixel centres and on shared edges (the fill rule), a few degenerate.
TriangleBatch random_triangles(std::uint32_t seed, std::size_t count) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  TriangleBatch b;
  for (std::size_t i = 0; i < count; ++i) {
    const int kind = int(rng() % 8);
    const float scale = kind < 4 ? 0.8f : kind < 6 ? 3.5f : kind == 6 ? 30.0f : 1.0f;
    const float cx = -4.0f + unit(rng) * (kWidth + 8.0f), cy = -4.0f + unit(rng) * (kHeight + 8.0f);
    ClipVertex v[3];
    for (int k = 0; k < 3; ++k) {
      float x = cx + (unit(rng) - 0.5f) * scale, y = cy + (unit(rng) - 0.5f) * scale;
      if (kind == 7) {  // on the 1/2-pixel grid: centres on corners and edges
        x = std::round(x * 2.0f) / 2.0f;
        y = std::round(y * 2.0f) / 2.0f;
      }
      v[k] = test::window_vertex(x, y, unit(rng), kWidth, kHeight);
    }
    if (rng() % 50 == 0) v[2] = v[1];  // zero area
    test::add_triangle(b, v[0], v[1], v[2]);
  }
  return b;
}

// The verdicts of both kernels for a batch, and setup_triangle's outcome for each triangle.
void check_against_setup(const TriangleBatch& batch, raster::FaceRule faces) {
  const raster::Viewport vp{kWidth, kHeight, 0.0, 1.0};
  std::vector<raster::ProjectedVertex> projected(batch.vertex_count());
  raster::project_vertices(batch.vertices.data(), projected.size(), batch.records(), vp, projected.data());
  const raster::TriageParams params{kWidth, kHeight, faces.cull_front, faces.cull_back, faces.front_cw};
  std::size_t decided[3] = {};
  for (std::size_t first = 0; first < batch.triangle_count(); first += raster::TriageCorners::kMax) {
    const int n = int(std::min<std::size_t>(raster::TriageCorners::kMax, batch.triangle_count() - first));
    // The plain kernel, then the AVX2 one where the CPU has it: the same verdicts.
    std::vector<raster::Triage> verdicts(static_cast<std::size_t>(n)), wide(static_cast<std::size_t>(n));
    const SimdPath path = simd_path();
    set_simd_path(SimdPath::Scalar);
    raster::triage_triangles(projected.data(), nullptr, first, n, params, verdicts.data());
    if (cpu_has_avx2()) {
      set_simd_path(SimdPath::Avx2);
      raster::triage_triangles(projected.data(), nullptr, first, n, params, wide.data());
      ASSERT_EQ(verdicts, wide) << "triangles " << first << " ..";
    }
    set_simd_path(path);
    for (int k = 0; k < n; ++k) {
      const std::size_t i = first + std::size_t(k);
      std::vector<raster::SetupTriangle> tris;
      std::vector<float> varyings;
      int pieces = 0;
      const raster::SetupOutcome outcome =
          raster::setup_triangle(batch, i, projected.data(), vp, faces, tris, varyings, pieces);
      const raster::Triage verdict = verdicts[std::size_t(k)];
      ASSERT_LE(std::uint8_t(verdict), 2) << "triangle " << i;
      ++decided[std::uint8_t(verdict)];
      if (verdict == Triage::kCulled) {
        EXPECT_EQ(outcome, raster::SetupOutcome::kCulled) << "triangle " << i;
        EXPECT_TRUE(tris.empty()) << "triangle " << i;
      } else if (verdict == Triage::kNoFragment) {
        EXPECT_EQ(outcome, raster::SetupOutcome::kRasterized) << "triangle " << i;
        EXPECT_EQ(pieces, 1) << "triangle " << i;
        EXPECT_TRUE(tris.empty()) << "triangle " << i << ": setup stored it, so it may cover a centre";
      }
    }
  }
  // Each verdict is met, so that every branch above was exercised.
  if (faces.cull_back && faces.cull_front) {  // every triangle is culled or clipped
    EXPECT_EQ(decided[2], 0u);
    return;
  }
  EXPECT_GT(decided[0], batch.triangle_count() / 20);
  EXPECT_GT(decided[2], batch.triangle_count() / 20);
  if (faces.cull_back || faces.cull_front) EXPECT_GT(decided[1], batch.triangle_count() / 10);
  else EXPECT_GT(decided[1], 0u);  // the zero-area ones
}

TEST(Triage, VerdictsAreSetupsOutcomes) {
  check_against_setup(random_triangles(1, 20000), raster::FaceRule{});
}

TEST(Triage, VerdictsAreSetupsOutcomesWithCulling) {
  const TriangleBatch b = random_triangles(2, 20000);
  check_against_setup(b, raster::FaceRule{false, true, false});
  check_against_setup(b, raster::FaceRule{true, false, true});
  check_against_setup(b, raster::FaceRule{true, true, false});
}

// A triangle that covers exactly one centre, through a corner of its box: kSetUp; moved by one
// 1/256 pixel so that the centre lies on its right (not owned) edge: kNoFragment.
TEST(Triage, OneCentreOnTheFillRulesEdge) {
  raster::TriageCorners corners{};
  // Pixel (3, 2)'s centre is (3.5, 2.5) = (896, 640) in 24.8. A CCW triangle whose vertical edge
  // at x = 896 runs upward is a right edge: the centre on it is outside.
  auto set = [&](int k, int x0, int y0, int x1, int y1, int x2, int y2) {
    corners.x[0][k] = x0, corners.y[0][k] = y0;
    corners.x[1][k] = x1, corners.y[1][k] = y1;
    corners.x[2][k] = x2, corners.y[2][k] = y2;
    corners.codes[k] = 0;
  };
  set(0, 896 - 100, 600, 896, 600, 896, 700);        // centre on the right edge: not covered
  set(1, 896 - 100, 600, 896 + 1, 600, 896 + 1, 700);  // one unit right: covered
  set(2, 896 + 100, 600, 896, 700, 896, 600);        // mirrored: the edge runs down, a left edge
  set(3, 896, 600, 896 + 100, 600, 896, 700);        // left edge x = 896 running down: covered
  const raster::TriageParams params{kWidth, kHeight, false, false, false};
  std::uint8_t out[4];
  raster::triage_kernel_scalar(corners, 0, 4, params, out);
  EXPECT_EQ(Triage(out[0]), Triage::kNoFragment);
  EXPECT_EQ(Triage(out[1]), Triage::kSetUp);
  EXPECT_EQ(Triage(out[2]), Triage::kSetUp);
  EXPECT_EQ(Triage(out[3]), Triage::kSetUp);
}

}  // namespace
}  // namespace tessref
