// User clip planes (gl_ClipDistance with GL_CLIP_DISTANCEi) and cull distances (gl_CullDistance):
// GL 4.6 13.7, with the plane order, arithmetic and non-finite rules of Mesa's draw module.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "raster/clip.h"
#include "raster_test_util.h"

namespace tessref {
namespace {

constexpr int kW = 128, kH = 64;

// A vertex inside the view volume (w = 1) whose varying 0 is a clip distance.
std::array<float, 5> vertex(float x, float y, float d) { return {x, y, 0.0f, 1.0f, d}; }

TEST(UserClip, ATriangleIsCutWhereItsDistanceIsZero) {
  const auto a = vertex(-0.5f, -0.5f, 1.0f), b = vertex(0.5f, -0.5f, 1.0f), c = vertex(0.0f, 0.5f, -1.0f);
  raster::ClipPolygon poly;
  ASSERT_EQ(raster::clip_triangle(a.data(), b.data(), c.data(), 1, 1.0f, 1.0f, poly, ~0u, {1u, 0}),
            raster::ClipResult::kKept);
  // a, b, then the cut on b -> c and on c -> a: each from the outside vertex c, t = -1 / (-1 - 1).
  ASSERT_EQ(poly.count, 4);
  EXPECT_EQ(poly.v[2].position, glm::vec4(0.25f, 0.0f, 0.0f, 1.0f));
  EXPECT_EQ(poly.v[3].position, glm::vec4(-0.25f, 0.0f, 0.0f, 1.0f));
  EXPECT_EQ(poly.v[2].varyings[0], 0.0f);
  EXPECT_EQ(poly.v[3].varyings[0], 0.0f);
  EXPECT_FALSE(poly.generated[0] || poly.generated[1]);
  EXPECT_TRUE(poly.generated[2] && poly.generated[3]);
  // The edge along the user plane (vertex 2 -> 3) is an edge of the polygon, unlike one along a
  // view plane: Mesa draws it in polygon mode line.
  EXPECT_TRUE(poly.boundary[2]);

  // The same plane not enabled: nothing is cut.
  ASSERT_EQ(raster::clip_triangle(a.data(), b.data(), c.data(), 1, 1.0f, 1.0f, poly), raster::ClipResult::kKept);
  EXPECT_EQ(poly.count, 3);
}

TEST(UserClip, AViewPlaneBeforeTheUserPlanes) {
  // Crosses x = w (plane 0) and the user plane: Mesa clips against the view planes first.
  const auto a = vertex(-0.5f, -0.5f, 1.0f), b = vertex(1.5f, -0.5f, 1.0f), c = vertex(0.0f, 0.5f, -1.0f);
  raster::ClipPolygon poly;
  ASSERT_EQ(raster::clip_triangle(a.data(), b.data(), c.data(), 1, 1.0f, 1.0f, poly, ~0u, {1u, 0}),
            raster::ClipResult::kKept);
  EXPECT_EQ(poly.count, 5);
  for (int k = 0; k < poly.count; ++k) {
    EXPECT_LE(poly.v[k].position.x, 1.0f) << k;
    EXPECT_GE(poly.v[k].varyings[0], 0.0f) << k;
  }
}

TEST(UserClip, NonFiniteDistancesDropThePrimitive) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  raster::ClipPolygon poly;
  for (const float bad : {nan, inf, -inf}) {
    const auto a = vertex(-0.5f, -0.5f, 1.0f), b = vertex(0.5f, -0.5f, 1.0f), c = vertex(0.0f, 0.5f, bad);
    EXPECT_EQ(raster::clip_triangle(a.data(), b.data(), c.data(), 1, 1.0f, 1.0f, poly, ~0u, {1u, 0}),
              raster::ClipResult::kInvalid)
        << bad;
    raster::ClipRecord ends[2];
    bool generated[2];
    EXPECT_EQ(raster::clip_line(a.data(), c.data(), 1, 1.0f, 1.0f, ends, generated, ~0u, {1u, 0}),
              raster::ClipResult::kInvalid);
  }
  // Wholly outside the plane: rejected.
  const auto a = vertex(-0.5f, -0.5f, -1.0f), b = vertex(0.5f, -0.5f, -2.0f), c = vertex(0.0f, 0.5f, -0.5f);
  EXPECT_EQ(raster::clip_triangle(a.data(), b.data(), c.data(), 1, 1.0f, 1.0f, poly, ~0u, {1u, 0}),
            raster::ClipResult::kRejected);
}

TEST(UserClip, CullDistancesDropWhatIsWhollyOutside) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float in[3][2] = {{-1.0f, 0.5f}, {-2.0f, 0.5f}, {-0.5f, -1.0f}};
  const float* v[3] = {in[0], in[1], in[2]};
  EXPECT_TRUE(raster::culled_by_distance(v, 0, 1));  // distance 0 negative at every corner
  EXPECT_FALSE(raster::culled_by_distance(v, 1, 1));  // distance 1 is not
  const float zero[3][1] = {{0.0f}, {-1.0f}, {nan}};
  const float* z[3] = {zero[0], zero[1], zero[2]};
  EXPECT_FALSE(raster::culled_by_distance(z, 0, 1));  // 0 is inside
  const float out[3][1] = {{-0.0f - 1e-30f}, {-1.0f}, {nan}};
  const float* o[3] = {out[0], out[1], out[2]};
  EXPECT_TRUE(raster::culled_by_distance(o, 0, 1));  // NaN counts as outside
}

// A full-viewport rectangle whose varying 0 is x_ndc: with GL_CLIP_DISTANCE0 it keeps the pixel
// centres with x_ndc >= 0, the right half.
TriangleBatch rectangle(float cull) {
  TriangleBatch b;
  b.num_varyings = 2;
  auto v = [&](float x, float y) {
    ClipVertex c;
    c.position = glm::vec4(x, y, 0.0f, 1.0f);
    c.varyings[0] = x;
    c.varyings[1] = cull;
    return c;
  };
  test::add_triangle(b, v(-1, -1), v(1, -1), v(1, 1));
  test::add_triangle(b, v(-1, -1), v(1, 1), v(-1, 1));
  return b;
}

TEST(UserClip, DrawsKeepWhatIsInsideTheEnabledPlanes) {
  test::VaryingProgram prog;
  RasterState state;
  state.distances = {0, 1, 1, 1};
  for (const std::uint8_t enables : {std::uint8_t(0), std::uint8_t(1), std::uint8_t(0xfe)}) {
    Framebuffer fb(kW, kH);
    state.clip_distances = enables;
    const RasterStats s = draw_triangles(rectangle(0.5f), state, prog, fb, Parallel(2));
    const bool clipped = enables & 1u;
    EXPECT_EQ(s.fragments_shaded, std::uint64_t(clipped ? kW / 2 * kH : kW * kH)) << int(enables);
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x)
        ASSERT_EQ(fb.depth[std::size_t(y) * kW + x] < 1.0f, !clipped || x >= kW / 2) << x << ", " << y;
  }
  // Cull distance 0 negative at every corner: both triangles are culled, enabled or not.
  Framebuffer fb(kW, kH);
  const RasterStats s = draw_triangles(rectangle(-1.0f), state, prog, fb, Parallel(2));
  EXPECT_EQ(s.triangles_culled, 2u);
  EXPECT_EQ(s.fragments_shaded, 0u);
}

// glClipPlane's planes (compatibility profile) with no clip distance written: dot(gl_Position,
// plane), or dot(clip vertex, plane) for a clip vertex carried as varyings.
TEST(UserClip, ClipPlanesTestTheClipVertex) {
  test::VaryingProgram prog;
  RasterState state;
  state.clip_distances = 1;
  state.clip_planes[0] = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);  // x >= 0
  {
    Framebuffer fb(kW, kH);
    const RasterStats s = draw_triangles(rectangle(0.5f), state, prog, fb, Parallel(2));  // gl_Position
    EXPECT_EQ(s.fragments_shaded, std::uint64_t(kW / 2 * kH));
    EXPECT_LT(fb.depth[std::size_t(kW - 1)], 1.0f);
  }
  // The clip vertex in varyings 0-3: (x_ndc, cull, 0, 0); the plane -x >= 0 keeps the left half.
  state.clip_planes[0] = glm::vec4(-1.0f, 0.0f, 0.0f, 0.0f);
  state.distances.clip_vertex_first = 0;
  TriangleBatch b = rectangle(0.5f);
  b.num_varyings = 4;
  Framebuffer fb(kW, kH);
  const RasterStats s = draw_triangles(b, state, prog, fb, Parallel(2));
  EXPECT_EQ(s.fragments_shaded, std::uint64_t(kW / 2 * kH));
  EXPECT_LT(fb.depth[0], 1.0f);
  EXPECT_EQ(fb.depth[std::size_t(kW - 1)], 1.0f);
}

}  // namespace
}  // namespace tessref
