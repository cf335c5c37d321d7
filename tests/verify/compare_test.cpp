// tessref verify's comparisons on made-up data: planted differences are found where they were
// planted, and agreement reports none.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "common/parallel.h"
#include "verify/compare.h"

namespace tessref {
namespace {

std::vector<TessDumpRecord> three_patches() {
  std::vector<TessDumpRecord> r;
  for (std::uint32_t p = 0; p < 3; ++p)
    for (const glm::vec3& c : {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1), glm::vec3(0.5f, 0.5f, 0)})
      r.push_back({p, c, c * float(p + 1), glm::normalize(c + 0.1f)});
  return r;
}

// The driver emits every generated point at least once, some more often (shared by triangles).
std::vector<TessDumpRecord> emitted(const std::vector<TessDumpRecord>& points) {
  std::vector<TessDumpRecord> e;
  for (std::size_t i = 0; i < points.size(); ++i) {
    e.push_back(points[i]);
    if (i % 2 == 0) e.push_back(points[i]);
  }
  return e;
}

TEST(Verify, IdenticalStreamsAgree) {
  const auto points = three_patches();
  const TessComparison c = compare_tess(emitted(points), points);
  EXPECT_EQ(c.patches, 3u);
  EXPECT_TRUE(c.coords_identical());
  EXPECT_EQ(c.unmatched_vertices, 0u);
  EXPECT_EQ(c.max_position_ulp, 0u);
  EXPECT_EQ(c.position_ulps[0], 3u * 18u);  // 18 emitted vertices, 3 components each
}

TEST(Verify, ACoordinateOffByOneBitIsFoundInItsPatch) {
  const auto points = three_patches();
  auto ref = emitted(points);
  for (TessDumpRecord& r : ref)
    if (r.patch_id == 1 && r.tess_coord == glm::vec3(0.5f, 0.5f, 0)) r.tess_coord.x = std::nextafter(0.5f, 1.0f);
  const TessComparison c = compare_tess(ref, points);
  EXPECT_EQ(c.patches_mismatched, 1u);
  EXPECT_EQ(c.first_mismatched_patch, 1);
  EXPECT_GE(c.unmatched_vertices, 1u);
}

TEST(Verify, APointNeverEmittedIsAMismatch) {
  const auto points = three_patches();
  std::vector<TessDumpRecord> ref;
  for (const TessDumpRecord& r : points)
    if (!(r.patch_id == 2 && r.tess_coord.z == 1.0f)) ref.push_back(r);
  const TessComparison c = compare_tess(ref, points);
  EXPECT_EQ(c.patches_mismatched, 1u);
  EXPECT_EQ(c.first_mismatched_patch, 2);
  EXPECT_EQ(c.unmatched_vertices, 0u);
}

TEST(Verify, MovedPatchHasTheLargestDistance) {
  const auto points = three_patches();
  auto ref = emitted(points);
  for (TessDumpRecord& r : ref)
    if (r.patch_id == 2) r.position.y += 0.03f;
  const TessComparison c = compare_tess(ref, points);
  EXPECT_TRUE(c.coords_identical());
  EXPECT_EQ(c.worst_position_patch, 2);
  EXPECT_NEAR(c.max_position_distance, 0.03, 1e-6);
  EXPECT_GT(c.max_position_ulp, 1000u);
}

// A flipped normal and one scaled by 2, relative to the longer normal: 2 and 0.5.
TEST(Verify, NormalDifferencesAreRelativeToTheLongerNormal) {
  const auto points = three_patches();
  EXPECT_EQ(compare_tess(emitted(points), points).max_normal_difference, 0.0);
  auto flipped = emitted(points);
  flipped[5].normal = -flipped[5].normal;
  TessComparison c = compare_tess(flipped, points);
  EXPECT_DOUBLE_EQ(c.max_normal_difference, 2.0);
  EXPECT_EQ(c.worst_normal_patch, flipped[5].patch_id);
  auto scaled = emitted(points);
  for (TessDumpRecord& r : scaled)
    if (r.patch_id == 2) r.normal *= 2.0f;
  c = compare_tess(scaled, points);
  EXPECT_NEAR(c.max_normal_difference, 0.5, 1e-7);
  EXPECT_EQ(c.worst_normal_patch, 2);
  EXPECT_TRUE(c.coords_identical());
  EXPECT_EQ(c.max_position_distance, 0.0);
}

// NaN is farther than no limit: it is counted apart, in its patch.
TEST(Verify, NonFiniteValuesOnOneSideAreCounted) {
  const auto points = three_patches();
  auto ref = emitted(points);
  ref[9].position.y = std::numeric_limits<float>::quiet_NaN();
  ref[14].normal.x = std::numeric_limits<float>::infinity();
  TessComparison c = compare_tess(ref, points);
  EXPECT_EQ(c.nonfinite_records, 2u);
  EXPECT_EQ(c.first_nonfinite_patch, ref[9].patch_id);
  // The same NaN on both sides (a shader dividing by zero on either) is agreement.
  auto mine = points;
  for (TessDumpRecord& r : mine) r.position.x = std::numeric_limits<float>::quiet_NaN();
  auto theirs = emitted(mine);
  EXPECT_EQ(compare_tess(theirs, mine).nonfinite_records, 0u);
}

// One patch of two triangles (indices into its points), emitted in other orders: a rotation of a
// triangle's corners and another order of triangles are the driver's choice; a reversal is not.
TEST(Verify, ReversedTrianglesAreFoundInTheirPatch) {
  std::vector<TessDumpRecord> points;
  for (std::uint32_t p = 0; p < 2; ++p)
    for (const glm::vec3& c : {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1), glm::vec3(0.5f, 0.5f, 0)})
      points.push_back({p, c, c, c});
  const std::vector<std::uint32_t> indices = {0, 1, 3, 3, 1, 2, 4, 5, 7, 7, 5, 6};
  const auto stream = [&](std::initializer_list<std::uint32_t> order) {
    std::vector<TessDumpRecord> e;
    for (std::uint32_t i : order) e.push_back(points[i]);
    return e;
  };
  const auto all = [](std::uint32_t) { return true; };
  EXPECT_TRUE(winding_differs(stream({0, 1, 3, 3, 1, 2, 4, 5, 7, 7, 5, 6}), points, indices, all).patches.empty());
  EXPECT_TRUE(winding_differs(stream({1, 2, 3, 1, 3, 0, 5, 7, 4, 7, 5, 6}), points, indices, all).patches.empty());
  const WindingDifference w = winding_differs(stream({0, 1, 3, 3, 1, 2, 4, 7, 5, 7, 5, 6}), points, indices, all);
  ASSERT_EQ(w.patches, std::vector<std::uint32_t>{1});
  EXPECT_EQ(w.triangles, 1u);
  EXPECT_EQ(w.first_patch_triangles, 1u);
  EXPECT_EQ(w.first_patch_total, 2u);
  // Patches that emit lines or points are not examined.
  EXPECT_TRUE(winding_differs(stream({0, 1, 3, 3, 1, 2, 4, 7, 5, 7, 5, 6}), points, indices,
                              [](std::uint32_t p) { return p != 1; })
                  .patches.empty());
}

TEST(Verify, UlpBucketsAreNamedByTheirRanges) {
  EXPECT_EQ(ulp_bucket_name(0), "0");
  EXPECT_EQ(ulp_bucket_name(2), "2");
  EXPECT_EQ(ulp_bucket_name(3), "3-4");
  EXPECT_EQ(ulp_bucket_name(4), "5-8");
  EXPECT_EQ(ulp_bucket_name(13), ">2048");
  // One ULP apart lands in bucket 1, four apart in "3-4".
  std::vector<TessDumpRecord> a = three_patches(), b = a;
  b[0].position.x = std::nextafter(std::nextafter(std::nextafter(std::nextafter(b[0].position.x, 2.f), 2.f), 2.f), 2.f);
  b[1].position.y = std::nextafter(b[1].position.y, 2.f);
  const TessComparison c = compare_tess(b, a);
  EXPECT_EQ(c.position_ulps[3], 1u);
  EXPECT_EQ(c.position_ulps[1], 1u);
  EXPECT_EQ(c.max_position_ulp, 4u);
}

// A disc of radius 10 in a 32x32 frame; the reference has one extra pixel on its edge and one
// stray pixel in a corner.
TEST(Verify, CoverageMismatchesByDistanceToTheSilhouette) {
  Framebuffer fb;
  fb.reset(32, 32, glm::vec4(0.0f), Parallel(1));
  FloatImage ref{32, 32, 1, std::vector<float>(32 * 32, 1.0f)};
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      if ((x - 16) * (x - 16) + (y - 16) * (y - 16) <= 100) {
        fb.depth[fb.index(x, 31 - y)] = 0.5f;  // the framebuffer's row 0 is the image's last
        ref.pixels[std::size_t(y) * 32 + x] = 0.5f;
      }
  CoverageComparison c = compare_coverage(ref, fb);
  EXPECT_EQ(c.mismatched, 0u);
  EXPECT_EQ(c.covered_reference, c.covered_tessref);
  ref.pixels[16 * 32 + 27] = 0.5f;  // just outside the disc's right edge (x = 26 is on it)
  ref.pixels[1 * 32 + 1] = 0.5f;    // far from it
  c = compare_coverage(ref, fb);
  EXPECT_EQ(c.mismatched, 2u);
  EXPECT_EQ(c.off_silhouette, 1u);
  EXPECT_EQ(c.heat[16 * 32 + 27], 1.0f);  // on the silhouette: distance 0
  EXPECT_GT(c.heat[1 * 32 + 1], 2.0f);
}

TEST(Verify, ColorFigures) {
  Rgb8Image a{2, 1, {10, 20, 30, 40, 50, 60}}, b = a;
  ColorComparison c = compare_color(a, b);
  EXPECT_EQ(c.within_1, 2u);
  EXPECT_TRUE(std::isinf(c.psnr));
  b.pixels[4] = 53;
  c = compare_color(a, b);
  EXPECT_EQ(c.within_1, 1u);
  EXPECT_EQ(c.within_2, 1u);
  EXPECT_EQ(c.max_difference, 3);
  EXPECT_NEAR(c.psnr, 10.0 * std::log10(255.0 * 255.0 / (9.0 / 6.0)), 1e-9);
}

TEST(Verify, EmissionOrderIsComparedTriangleByTriangle) {
  // Patch 0 and 1: two triangles each over four points; the driver emits patch 1's second
  // triangle rotated (same triangle, other first vertex): that patch's order differs.
  std::vector<TessDumpRecord> points;
  for (std::uint32_t p = 0; p < 2; ++p)
    for (const glm::vec3& c : {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1), glm::vec3(0.5f, 0.5f, 0)})
      points.push_back({p, c, c, c});
  const std::vector<std::uint32_t> indices = {0, 3, 2, 3, 1, 2, 4, 7, 6, 7, 5, 6};
  std::vector<TessDumpRecord> emitted;
  for (std::uint32_t i : indices) emitted.push_back(points[i]);
  EXPECT_TRUE(emission_order_differs(emitted, points, indices).empty());
  std::rotate(emitted.begin() + 9, emitted.begin() + 10, emitted.end());
  EXPECT_EQ(emission_order_differs(emitted, points, indices), std::vector<std::uint32_t>{1});
  // A patch tessref did not draw at all differs too.
  emitted.push_back({7, glm::vec3(1, 0, 0), glm::vec3(0.0f), glm::vec3(0.0f)});
  EXPECT_EQ(emission_order_differs(emitted, points, indices), (std::vector<std::uint32_t>{1, 7}));
}

}  // namespace
}  // namespace tessref
