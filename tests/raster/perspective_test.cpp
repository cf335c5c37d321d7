// Perspective-correct varyings: a floor plane seen in perspective carries its world coordinates
// as varyings; each covered pixel must hold the point where its center's eye ray meets the floor.
#include <cmath>

#include <gtest/gtest.h>

#include "raster_test_util.h"

namespace tessref {
namespace {

constexpr int kW = 256, kH = 256;

// 90 degree square frustum, near 1, far 16, built by hand so that x_c = x, y_c = y, w_c = -z are
// exact: with the corners below, every window coordinate is a multiple of 1/256 pixel, so
// sub-pixel snapping moves nothing and the analytic value is the exact expectation.
ClipVertex project(glm::vec3 p) {
  const float n = 1.0f, f = 16.0f;
  ClipVertex v;
  v.position = glm::vec4(p.x, p.y, -(f + n) / (f - n) * p.z - 2.0f * f * n / (f - n), -p.z);
  v.varyings[0] = p.x;
  v.varyings[1] = p.y;
  v.varyings[2] = p.z;
  return v;
}

// Renders the floor quad y = -1, x in [-4, 4], z in [z_near_edge, -8] and compares each covered
// pixel with the analytic ray-floor intersection.
void check_floor(float z_near_edge, double tolerance) {
  TriangleBatch b;
  b.num_varyings = 3;
  const ClipVertex a = project({-4, -1, z_near_edge}), c = project({4, -1, z_near_edge});
  const ClipVertex d = project({4, -1, -8}), e = project({-4, -1, -8});
  test::add_triangle(b, a, c, d);
  test::add_triangle(b, a, d, e);
  Framebuffer fb(kW, kH);
  test::VaryingProgram prog;
  draw_triangles(b, RasterState{}, prog, fb, Parallel(2));

  int covered = 0;
  double worst = 0.0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const std::size_t i = fb.index(x, y);
      if (!(fb.depth[i] < 1.0f)) continue;
      ++covered;
      // The eye ray through the pixel center is (x_ndc, y_ndc, -1); it meets y = -1 at
      // t = -1 / y_ndc.
      const double x_ndc = 2.0 * (x + 0.5) / kW - 1.0, y_ndc = 2.0 * (y + 0.5) / kH - 1.0;
      ASSERT_LT(y_ndc, 0.0);
      const double qx = -x_ndc / y_ndc, qz = 1.0 / y_ndc;
      const glm::vec4 got = fb.color[i];
      auto rel = [](double g, double want) {
        return std::abs(g - want) / std::max(1.0, std::abs(want));
      };
      worst = std::max({worst, rel(got.x, qx), rel(got.z, qz), rel(got.y, -1.0)});
      ASSERT_LE(rel(got.x, qx), tolerance) << x << "," << y;
      ASSERT_LE(rel(got.z, qz), tolerance) << x << "," << y;
      ASSERT_EQ(got.y, -1.0f);  // constant varyings stay exact
      // gl_FragCoord.w = 1 / w_clip = 1 / -z.
      ASSERT_LE(rel(fb.aux[i].x, -1.0 / qz), tolerance) << x << "," << y;
    }
  EXPECT_GT(covered, kW * kH / 8);
  ::testing::Test::RecordProperty("worst_relative_error_ppm", std::to_string(worst * 1e6));
}

TEST(RasterPerspective, FloorVaryingsMatchTheAnalyticIntersection) {
  // Barycentrics come from exact integer edge functions in double; the perspective weights are
  // rounded to float and the varying combined in float: a few float ulps of values up to 8, about
  // 1e-6 relative. 1e-4 leaves margin, while affine (screen-linear) interpolation would be off by
  // up to several world units here.
  check_floor(-2.0f, 1e-4);
}

TEST(RasterPerspective, FloorClippedByTheNearPlane) {
  // The near edge at z = -0.25 is cut by the near plane z = -1; the cut vertices are rounded in
  // float and snapped to 1/256 pixel (at most 1/512 pixel off, about 1.5e-5 world units where the
  // floor meets the near plane), so the same 1e-4 relative bound (values >= 1) still holds.
  check_floor(-0.25f, 1e-4);
}

}  // namespace
}  // namespace tessref
