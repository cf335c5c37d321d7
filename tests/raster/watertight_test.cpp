// Shared edges are drawn exactly once: meshes whose union is the whole screen must hit every pixel
// exactly once, whatever the sub-pixel vertex positions, the clip w, or guard-band clipping.
#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "raster_test_util.h"

namespace tessref {
namespace {

constexpr int kW = 160, kH = 128;

// Draws with raw coverage counting (depths made strictly decreasing) and checks every pixel of
// the screen was hit exactly once.
void expect_covered_once(TriangleBatch batch, int threads, const char* what) {
  test::make_depth_decreasing(batch);
  Framebuffer fb(kW, kH);
  test::CountingProgram counter(kW, kH);
  RasterStats s = draw_triangles(batch, RasterState{}, counter, fb, Parallel(threads));
  EXPECT_EQ(s.fragments_shaded, std::uint64_t(kW) * kH) << what;
  int holes = 0, doubles = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const std::uint32_t c = counter.at(x, y);
      holes += c == 0;
      doubles += c > 1;
    }
  EXPECT_EQ(holes, 0) << what;
  EXPECT_EQ(doubles, 0) << what;
}

// An nx x ny grid of quads over the screen (window coordinates), interior vertices jittered by
// up to 0.2 cell (< 1/4 keeps every quad convex, so either diagonal splits it without overlap);
// border vertices on the screen border.
TriangleBatch jittered_grid(int nx, int ny, std::uint32_t seed, bool random_w, bool flip_some) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> jitter(-0.2f, 0.2f);
  std::uniform_real_distribution<float> wdist(0.25f, 4.0f);
  const float cw = float(kW) / nx, ch = float(kH) / ny;
  std::vector<ClipVertex> v((nx + 1) * (ny + 1));
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      float x = i * cw, y = j * ch;
      if (i > 0 && i < nx) x += jitter(rng) * cw;
      if (j > 0 && j < ny) y += jitter(rng) * ch;
      v[j * (nx + 1) + i] = test::window_vertex(x, y, 0.5f, kW, kH, random_w ? wdist(rng) : 1.0f);
    }
  TriangleBatch b;
  std::bernoulli_distribution coin(0.5);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const ClipVertex& a = v[j * (nx + 1) + i];
      const ClipVertex& bq = v[j * (nx + 1) + i + 1];
      const ClipVertex& c = v[(j + 1) * (nx + 1) + i + 1];
      const ClipVertex& d = v[(j + 1) * (nx + 1) + i];
      // Either diagonal; winding flipped at random on some (orientation must not matter).
      const bool diag = coin(rng);
      const bool flip = flip_some && coin(rng);
      auto tri = [&](const ClipVertex& p, const ClipVertex& q, const ClipVertex& r) {
        if (flip)
          test::add_triangle(b, p, r, q);
        else
          test::add_triangle(b, p, q, r);
      };
      if (diag) {
        tri(a, bq, c);
        tri(a, c, d);
      } else {
        tri(a, bq, d);
        tri(bq, c, d);
      }
    }
  return b;
}

TEST(RasterWatertight, JitteredGrid) {
  for (std::uint32_t seed : {1u, 2u, 3u}) {
    expect_covered_once(jittered_grid(23, 17, seed, false, false), 1, "grid, w = 1");
    expect_covered_once(jittered_grid(40, 31, seed + 10, true, true), 4,
                        "grid, random w, mixed winding");
  }
}

TEST(RasterWatertight, FineGridOfSubPixelTriangles) {
  // Cells smaller than a pixel: most triangles cover no center at all, none may be hit twice.
  expect_covered_once(jittered_grid(300, 250, 7, false, true), 2, "sub-pixel grid");
}

// A fan around a center vertex at a random sub-pixel position whose rim is a polygon around the
// screen at `radius` pixels from its middle (far beyond the guard band for large radii).
TriangleBatch fan(int segments, float radius, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const ClipVertex center =
      test::window_vertex(20.0f + u(rng) * (kW - 40), 20.0f + u(rng) * (kH - 40), 0.5f, kW, kH);
  std::vector<ClipVertex> rim;
  const float step = 2.0f * 3.14159265f / segments;
  for (int k = 0; k < segments; ++k) {
    const float a = (k + 0.3f + 0.4f * u(rng)) * step;  // random angles, still in order
    rim.push_back(test::window_vertex(kW * 0.5f + radius * std::cos(a),
                                      kH * 0.5f + radius * std::sin(a), 0.5f, kW, kH,
                                      0.5f + 2.0f * u(rng)));
  }
  TriangleBatch b;
  for (int k = 0; k < segments; ++k) test::add_triangle(b, center, rim[k], rim[(k + 1) % segments]);
  return b;
}

TEST(RasterWatertight, FanAroundSharedCenter) {
  for (std::uint32_t seed : {11u, 12u, 13u}) {
    expect_covered_once(fan(37, 150.0f, seed), 1, "fan, rim just off screen");
    expect_covered_once(fan(64, 100000.0f, seed), 2, "fan, rim beyond the guard band");
    expect_covered_once(fan(9, 3.0e7f, seed), 3, "fan, huge rim");
  }
}

TEST(RasterWatertight, VertexExactlyOnPixelCenters) {
  // A fan whose center and rim sit on pixel centers and pixel corners: the fill rule decides.
  TriangleBatch b;
  const ClipVertex c = test::window_vertex(80.5f, 64.5f, 0.5f, kW, kH);
  const float rim[][2] = {{-20, -20},   {80.5f, -20}, {200, -20},   {200, 64.5f}, {200, 200},
                          {80.5f, 200}, {-20, 200},   {-20, 64.5f}, {-20, 10.5f}};
  const int n = sizeof(rim) / sizeof(rim[0]);
  for (int k = 0; k < n; ++k) {
    const auto& p = rim[k];
    const auto& q = rim[(k + 1) % n];
    test::add_triangle(b, c, test::window_vertex(p[0], p[1], 0.5f, kW, kH),
                       test::window_vertex(q[0], q[1], 0.5f, kW, kH));
  }
  expect_covered_once(b, 1, "fan through pixel centers");
}

}  // namespace
}  // namespace tessref

namespace tessref {
namespace {

TEST(RasterWatertight, FloorGridCutByTheNearPlane) {
  // A jittered floor grid (y = -1) running from behind the eye to far ahead: edges shared by two
  // triangles are cut by the near plane at the same point from both sides, so below the horizon
  // every pixel is hit exactly once and nowhere twice.
  const glm::mat4 proj = glm::perspective(glm::radians(60.0f), float(kW) / kH, 0.3f, 1000.0f);
  std::mt19937 rng(77);
  std::uniform_real_distribution<float> jitter(-0.2f, 0.2f);
  const int n = 40;
  const float x0 = -200.0f, z0 = 5.0f, cell = 10.0f;  // x in [-200, 200], z in [5, -395]
  std::vector<ClipVertex> v((n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const float x = x0 + cell * (i + ((i > 0 && i < n) ? jitter(rng) : 0.0f));
      const float z = z0 - cell * (j + ((j > 0 && j < n) ? jitter(rng) : 0.0f));
      v[j * (n + 1) + i].position = proj * glm::vec4(x, -1.0f, z, 1.0f);
    }
  TriangleBatch b;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const ClipVertex &a = v[j * (n + 1) + i], &c = v[j * (n + 1) + i + 1];
      const ClipVertex &d = v[(j + 1) * (n + 1) + i + 1], &e = v[(j + 1) * (n + 1) + i];
      test::add_triangle(b, a, c, d);
      test::add_triangle(b, a, d, e);
    }
  test::make_depth_decreasing(b);
  Framebuffer fb(kW, kH);
  test::CountingProgram counter(kW, kH);
  const RasterStats s = draw_triangles(b, RasterState{}, counter, fb, Parallel(2));
  EXPECT_GT(s.triangles_rasterized, s.triangles_in - s.triangles_clipped_away);  // cut into pieces
  // Rows whose centers are below y_ndc = -0.01 look at floor points nearer than about 173 units,
  // where the floor (|x| <= 200) is wider than the view: there every pixel sees the floor.
  int holes = 0, doubles = 0, checked = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const std::uint32_t c = counter.at(x, y);
      doubles += c > 1;
      const double y_ndc = 2.0 * (y + 0.5) / kH - 1.0;
      if (y_ndc < -0.01) {
        ++checked;
        holes += c == 0;
      }
    }
  EXPECT_EQ(doubles, 0);
  EXPECT_EQ(holes, 0);
  EXPECT_GT(checked, kW * kH / 3);
}

}  // namespace
}  // namespace tessref
