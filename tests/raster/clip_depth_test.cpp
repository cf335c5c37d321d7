// Clipping against near and far, triangles behind the eye, invalid input, and the depth test.
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "raster_test_util.h"

namespace tessref {
namespace {

constexpr int kW = 128, kH = 96;

struct Camera {
  glm::mat4 proj = glm::perspective(glm::radians(60.0f), float(kW) / kH, 0.5f, 100.0f);
  float near = 0.5f;
  // Eye at the origin looking down -z; varyings 0..2 carry the view-space position.
  ClipVertex vertex(glm::vec3 p) const {
    ClipVertex v;
    v.position = proj * glm::vec4(p, 1.0f);
    v.varyings[0] = p.x;
    v.varyings[1] = p.y;
    v.varyings[2] = p.z;
    return v;
  }
  // The view-space direction through the center of pixel (x, y).
  glm::dvec3 ray(int x, int y) const {
    const double x_ndc = 2.0 * (x + 0.5) / kW - 1.0, y_ndc = 2.0 * (y + 0.5) / kH - 1.0;
    return {x_ndc / proj[0][0], y_ndc / proj[1][1], -1.0};
  }
};

void expect_all_finite(const Framebuffer& fb) {
  for (std::size_t i = 0; i < fb.color.size(); ++i) {
    ASSERT_TRUE(std::isfinite(fb.depth[i])) << i;
    ASSERT_GE(fb.depth[i], 0.0f);
    ASSERT_LE(fb.depth[i], 1.0f);
    for (int c = 0; c < 4; ++c) {
      ASSERT_TRUE(std::isfinite(fb.color[i][c])) << i;
      ASSERT_TRUE(std::isfinite(fb.aux[i][c])) << i;
    }
  }
}

TEST(RasterClip, TriangleCrossingTheNearPlaneIsClipped) {
  // On the floor y = -1, one vertex behind the eye (w < 0), two in front.
  const Camera cam;
  const glm::dvec3 p[3] = {{0, -1, 2}, {-3, -1, -4}, {3, -1, -4}};
  TriangleBatch b;
  b.num_varyings = 3;
  test::add_triangle(b, cam.vertex(p[0]), cam.vertex(p[1]), cam.vertex(p[2]));
  Framebuffer fb(kW, kH);
  test::VaryingProgram prog;
  const RasterStats s = draw_triangles(b, RasterState{}, prog, fb, Parallel(2));
  EXPECT_EQ(s.triangles_in, 1u);
  EXPECT_EQ(s.triangles_clipped_away, 0u);
  // The near plane cuts a corner off, and the left and right sides of the viewport (where llvmpipe
  // clips, and so tessref) cut two more: a hexagon, 4 pieces.
  EXPECT_EQ(s.triangles_rasterized, 4u);
  EXPECT_GT(s.fragments_shaded, 500u);
  expect_all_finite(fb);

  // Per pixel: the eye ray meets the floor at q; the pixel is covered iff q is in the triangle and
  // in front of the near plane. Pixels within a small margin of either boundary are skipped.
  int checked = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const glm::dvec3 d = cam.ray(x, y);
      const bool covered = fb.depth[fb.index(x, y)] < 1.0f;
      if (d.y >= -1e-9) {  // looks at or above the horizon
        EXPECT_FALSE(covered) << x << "," << y;
        continue;
      }
      const glm::dvec3 q = d * (-1.0 / d.y);
      auto edge = [&](glm::dvec3 a, glm::dvec3 c) {  // signed distance from the edge, in the floor
        const glm::dvec2 e(c.x - a.x, c.z - a.z), r(q.x - a.x, q.z - a.z);
        return (e.x * r.y - e.y * r.x) / glm::length(e);
      };
      const double d0 = edge(p[0], p[1]), d1 = edge(p[1], p[2]), d2 = edge(p[2], p[0]);
      const bool same_sign = (d0 > 0 && d1 > 0 && d2 > 0) || (d0 < 0 && d1 < 0 && d2 < 0);
      const double margin = 0.02 * -q.z;  // about 1/20 pixel at this field of view and size
      const double near_dist = -q.z - cam.near;
      if (std::min({std::abs(d0), std::abs(d1), std::abs(d2)}) < margin ||
          std::abs(near_dist) < margin)
        continue;
      ++checked;
      EXPECT_EQ(covered, same_sign && near_dist > 0) << x << "," << y;
      if (covered) {
        // The interpolated view-space position is the floor point on this pixel's ray.
        const glm::vec4 v = fb.color[fb.index(x, y)];
        EXPECT_NEAR(v.y, -1.0, 1e-4);
        EXPECT_NEAR(v.x, q.x, 1e-4 * std::max(1.0, std::abs(q.x)));
        EXPECT_NEAR(v.z, q.z, 1e-4 * std::max(1.0, std::abs(q.z)));
      }
    }
  EXPECT_GT(checked, kW * kH / 3);  // the upper half looks above the horizon
}

// GL_DEPTH_CLAMP: a floor triangle reaching past the far plane (100) keeps its far part, at depth
// 1 (clamped at the test; GL_LEQUAL lets it pass against the cleared 1), and the part in front of
// the far plane is unchanged; a triangle wholly behind the eye still draws nothing (the viewport's
// sides clip it, which keeps w > 0).
TEST(RasterClip, DepthClampKeepsWhatTheFarPlaneWouldClip) {
  const Camera cam;
  TriangleBatch b;
  b.num_varyings = 3;
  test::add_triangle(b, cam.vertex({0, -1, -4}), cam.vertex({-300, -1, -300}), cam.vertex({300, -1, -300}));
  test::VaryingProgram prog;
  Framebuffer clipped(kW, kH), clamped(kW, kH);
  RasterState state;
  state.depth_func = DepthFunc::kLessEqual;
  draw_triangles(b, state, prog, clipped, Parallel(2));
  state.depth_clamp = true;
  draw_triangles(b, state, prog, clamped, Parallel(2));
  // Different cuts (the far plane's, or none) give other pieces with other corners, so a pixel
  // centre on the triangle's edge may go either way: a handful, counted.
  int kept = 0, same = 0, edge = 0;
  for (std::size_t i = 0; i < clamped.depth.size(); ++i) {
    const bool was_drawn = clipped.color[i] != glm::vec4(0.0f), is_drawn = clamped.color[i] != glm::vec4(0.0f);
    if (was_drawn && is_drawn) {
      // Interpolated over other pieces (other corners): a few ulps apart.
      EXPECT_NEAR(clamped.depth[i], clipped.depth[i], 1e-6) << i % kW << "," << i / kW;
      ++same;
    } else if (is_drawn && clamped.depth[i] == 1.0f) {
      ++kept;  // past the far plane
    } else if (was_drawn || is_drawn) {
      ++edge;
    }
  }
  std::printf("[ figures  ] depth clamp: %d pixels as before, %d kept past the far plane, %d on an edge\n", same, kept, edge);
  EXPECT_LE(edge, 8);
  EXPECT_GT(same, 1000);
  EXPECT_GT(kept, 50);

  TriangleBatch behind;
  test::add_triangle(behind, cam.vertex({0, 1, 3}), cam.vertex({-1, -1, 3}), cam.vertex({1, -1, 3}));
  Framebuffer fb(kW, kH);
  EXPECT_EQ(draw_triangles(behind, state, prog, fb, Parallel(1)).fragments_shaded, 0u);
}

TEST(RasterClip, TriangleBehindTheEyeRendersNothing) {
  // Behind the eye its naive projection would land on screen (mirrored): w < 0 everywhere.
  const Camera cam;
  TriangleBatch b;
  test::add_triangle(b, cam.vertex({0, 1, 3}), cam.vertex({-1, -1, 3}), cam.vertex({1, -1, 3}));
  test::add_triangle(b, cam.vertex({0, 1, 3}), cam.vertex({1, -1, 3}), cam.vertex({-1, -1, 3}));
  Framebuffer fb(kW, kH);
  test::VaryingProgram prog;
  const RasterStats s = draw_triangles(b, RasterState{}, prog, fb, Parallel(1));
  EXPECT_EQ(s.triangles_in, 2u);
  EXPECT_EQ(s.triangles_clipped_away, 2u);
  EXPECT_EQ(s.fragments_shaded, 0u);
  for (float d : fb.depth) ASSERT_EQ(d, 1.0f);
}

TEST(RasterClip, FarPlaneCutsAlongDepth) {
  // Screen-space triangle (w = 1) whose window depth goes from 0.25 to 2: pixels past depth 1 are
  // clipped away. Depth is linear in x here: z_w(x) = 0.25 + 1.75 (x - 8) / 112.
  TriangleBatch b;
  test::add_triangle(b, test::window_vertex(8, 8, 0.25f, kW, kH),
                     test::window_vertex(120, 8, 2.0f, kW, kH),
                     test::window_vertex(8, 88, 0.25f, kW, kH));
  test::add_triangle(b, test::window_vertex(120, 8, 2.0f, kW, kH),
                     test::window_vertex(120, 88, 2.0f, kW, kH),
                     test::window_vertex(8, 88, 0.25f, kW, kH));
  Framebuffer fb(kW, kH);
  test::VaryingProgram prog;
  draw_triangles(b, RasterState{}, prog, fb, Parallel(1));
  expect_all_finite(fb);
  for (int y = 8; y < 88; ++y)
    for (int x = 8; x < 120; ++x) {
      const double z = 0.25 + 1.75 * (x + 0.5 - 8) / 112.0;
      if (std::abs(z - 1.0) < 1e-3) continue;
      const float d = fb.depth[fb.index(x, y)];
      EXPECT_EQ(d < 1.0f, z < 1.0) << x << "," << y;
      if (d < 1.0f) {
        EXPECT_NEAR(d, z, 1e-5);
      }
    }
}

TEST(RasterClip, InvalidPositionsAreDroppedWithoutHarm) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  TriangleBatch b;
  auto v = [](float x, float y, float z, float w) {
    ClipVertex c;
    c.position = glm::vec4(x, y, z, w);
    return c;
  };
  test::add_triangle(b, v(nan, 0, 0, 1), v(1, 0, 0, 1), v(0, 1, 0, 1));
  test::add_triangle(b, v(0, 0, 0, nan), v(1, 0, 0, 1), v(0, 1, 0, 1));
  test::add_triangle(b, v(-1, -1, 0, 1), v(inf, 0, 0, 1), v(0, 1, 0, 1));
  test::add_triangle(b, v(-1, -1, 0, 1), v(1, -1, -inf, 1), v(0, 1, 0, 1));
  test::add_triangle(b, v(0, 0, 0, 0), v(1, 0, 0, 1), v(0, 1, 0, 1));  // a vertex at the eye
  test::add_triangle(b, v(0, 0, 0, 0), v(0, 0, 0, 0), v(0, 0, 0, 0));  // all at the eye
  test::add_triangle(b, v(-1e30f, -1e30f, 0, 1), v(1e30f, -1e30f, 0, 1), v(0, 1e30f, 0, 1));
  test::add_triangle(b, v(-1e-30f, 0, 0, 1e-30f), v(1, -1, 0, 1), v(1, 1, 0, 1));  // tiny w
  Framebuffer fb(kW, kH);
  test::VaryingProgram prog;
  const RasterStats s = draw_triangles(b, RasterState{}, prog, fb, Parallel(2));
  EXPECT_EQ(s.triangles_in, 8u);
  EXPECT_EQ(s.triangles_clipped_away, 6u);  // the six with a non-finite or w = 0 position
  // The tiny-w one covers x_ndc >= 0, the right half (as llvmpipe: raster_vs_llvmpipe_test). The
  // huge one collapses to a point in float clipping at the viewport sides and draws nothing
  // (llvmpipe, clipping the same planes, draws 4,608 pixels of it: a known difference).
  EXPECT_EQ(s.fragments_shaded, std::uint64_t(kW) * kH / 2);
  expect_all_finite(fb);
}

struct Flat : FragmentProgram {
  glm::vec4 c;
  explicit Flat(glm::vec4 color) : c(color) {}
  FragmentOutput shade(const FragmentInput&) const override { return {c, glm::vec4(0.0f)}; }
};

// The fragment color comes from varyings 0..3, so each triangle can carry its own color.
TriangleBatch colored(glm::vec2 a, glm::vec2 b, glm::vec2 c, float z, glm::vec4 color) {
  TriangleBatch t;
  t.num_varyings = 4;
  for (glm::vec2 p : {a, b, c}) {
    ClipVertex v = test::window_vertex(p.x, p.y, z, kW, kH);
    for (int k = 0; k < 4; ++k) v.varyings[k] = color[k];
    t.vertices.push_back(v);
  }
  return t;
}

TEST(RasterDepth, NearerTriangleWinsInEitherOrder) {
  const glm::vec4 red(1, 0, 0, 1), blue(0, 0, 1, 1);
  const TriangleBatch near_red = colored({10, 10}, {100, 20}, {40, 80}, 0.3f, red);
  const TriangleBatch far_blue = colored({20, 5}, {110, 60}, {5, 70}, 0.6f, blue);
  test::VaryingProgram prog;
  for (bool red_first : {true, false}) {
    TriangleBatch b = red_first ? near_red : far_blue;
    const TriangleBatch& second = red_first ? far_blue : near_red;
    b.vertices.insert(b.vertices.end(), second.vertices.begin(), second.vertices.end());
    Framebuffer fb(kW, kH);
    draw_triangles(b, RasterState{}, prog, fb, Parallel(2));
    // Each triangle alone, to know which pixels each covers.
    Framebuffer fr(kW, kH), fbl(kW, kH);
    draw_triangles(near_red, RasterState{}, prog, fr, Parallel(1));
    draw_triangles(far_blue, RasterState{}, prog, fbl, Parallel(1));
    int overlap = 0;
    for (std::size_t i = 0; i < fb.color.size(); ++i) {
      const bool in_red = fr.depth[i] < 1.0f, in_blue = fbl.depth[i] < 1.0f;
      overlap += in_red && in_blue;
      const glm::vec4 expected = in_red ? red : in_blue ? blue : glm::vec4(0.0f);
      ASSERT_EQ(fb.color[i], expected) << i << (red_first ? " red first" : " blue first");
      ASSERT_EQ(fb.depth[i], in_red ? 0.3f : in_blue ? 0.6f : 1.0f) << i;
    }
    EXPECT_GT(overlap, 1000);
  }
}

TEST(RasterDepth, EqualDepthKeepsTheEarlierTriangle) {
  // Depth test LESS: a later fragment at equal depth fails.
  TriangleBatch b = colored({0, 0}, {128, 0}, {0, 96}, 0.5f, glm::vec4(1, 0, 0, 1));
  const TriangleBatch second = colored({0, 0}, {128, 0}, {128, 96}, 0.5f, glm::vec4(0, 1, 0, 1));
  b.vertices.insert(b.vertices.end(), second.vertices.begin(), second.vertices.end());
  Framebuffer fb(kW, kH);
  test::VaryingProgram prog;
  const RasterStats s = draw_triangles(b, RasterState{}, prog, fb, Parallel(2));
  EXPECT_EQ(fb.color[fb.index(100, 10)], glm::vec4(1, 0, 0, 1));
  EXPECT_EQ(fb.color[fb.index(120, 80)], glm::vec4(0, 1, 0, 1));
  std::uint64_t covered = 0;
  for (float d : fb.depth) covered += d < 1.0f;
  EXPECT_EQ(covered, std::uint64_t(kW) * kH - 128 * 48 / 2);  // all but the top wedge
  EXPECT_EQ(s.fragments_shaded, covered);                     // the overlap is shaded only once
}

TEST(RasterDepth, DepthRangeMapsWindowDepth) {
  // z_w = n + (f - n)(z_ndc + 1)/2: with n = 0.25, f = 0.75, z_ndc = 0.5 gives 0.625.
  TriangleBatch b;
  ClipVertex v[3];
  const glm::vec2 xy[3] = {{-1, -1}, {3, -1}, {-1, 3}};
  for (int k = 0; k < 3; ++k) {
    v[k].position = glm::vec4(xy[k] * 2.0f, 0.5f * 2.0f, 2.0f);  // w = 2
  }
  test::add_triangle(b, v[0], v[1], v[2]);
  RasterState state;
  state.depth_range_near = 0.25f;
  state.depth_range_far = 0.75f;
  Framebuffer fb(kW, kH);
  test::VaryingProgram prog;
  const RasterStats s = draw_triangles(b, state, prog, fb, Parallel(1));
  EXPECT_EQ(s.fragments_shaded, std::uint64_t(kW) * kH);
  for (std::size_t i = 0; i < fb.depth.size(); ++i) {
    ASSERT_EQ(fb.depth[i], 0.625f);
    ASSERT_EQ(fb.aux[i].x, 0.5f);  // gl_FragCoord.w = 1 / w_clip
  }
}

}  // namespace
}  // namespace tessref

namespace tessref {
namespace {

TEST(RasterInput, EmptyBatchesAndFramebuffersAndOversizedViewports) {
  test::VaryingProgram prog;
  Framebuffer fb(8, 8);
  TriangleBatch empty;
  EXPECT_EQ(draw_triangles(empty, RasterState{}, prog, fb, Parallel(2)).triangles_in, 0u);

  TriangleBatch one;
  test::add_triangle(one, test::window_vertex(0, 0, 0.5f, 8, 8),
                     test::window_vertex(8, 0, 0.5f, 8, 8), test::window_vertex(0, 8, 0.5f, 8, 8));
  one.num_varyings = 12;  // a varying the vertices do not write reads as its zero initializer
  // Centers with x + y < 7; the 8 on the hypotenuse (a right edge) are outside.
  EXPECT_EQ(draw_triangles(one, RasterState{}, prog, fb, Parallel(1)).fragments_shaded, 28u);

  Framebuffer none;  // 0 x 0: nothing to draw into
  const RasterStats s = draw_triangles(one, RasterState{}, prog, none, Parallel(1));
  EXPECT_EQ(s.triangles_in, 1u);
  EXPECT_EQ(s.fragments_shaded, 0u);

  // Wider than the 24.8 guard band allows (kMaxViewportPixels): refused rather than overflowed.
  Framebuffer wide;
  wide.width = 20000;
  wide.height = 1;
  wide.color.resize(20000);
  wide.depth.resize(20000, 1.0f);
  EXPECT_THROW(draw_triangles(one, RasterState{}, prog, wide, Parallel(1)), std::invalid_argument);
}

}  // namespace
}  // namespace tessref
