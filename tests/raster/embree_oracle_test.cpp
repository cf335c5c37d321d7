// Embree 3 as an independent oracle (tests/raster/embree_oracle.h) on random screen-space
// triangles and spheres.
#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "embree_oracle.h"
#include "raster_test_util.h"

namespace tessref {
namespace {

using test::compare_with_embree;
using test::OracleResult;

void record(const OracleResult& r) {
  ::testing::Test::RecordProperty("compared", r.compared);
  ::testing::Test::RecordProperty("excluded", r.excluded);
  ::testing::Test::RecordProperty("worst_relative_depth_vs_exact_ppb", int(r.worst_vs_exact * 1e9));
  ::testing::Test::RecordProperty("worst_relative_depth_vs_embree_ppb", int(r.worst_vs_ray * 1e9));
}

TEST(RasterEmbreeOracle, RandomScreenSpaceTriangles) {
  constexpr int kW = 256, kH = 192;
  std::mt19937 rng(2024);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  TriangleBatch b;
  for (int t = 0; t < 3000; ++t) {
    // Sizes from about a pixel to a third of the screen; some reach off screen.
    const float size = std::exp(u(rng) * std::log(80.0f));
    const glm::vec2 c(-20.0f + u(rng) * (kW + 40), -20.0f + u(rng) * (kH + 40));
    ClipVertex v[3];
    for (auto& vk : v) {
      const glm::vec2 p = c + size * glm::vec2(u(rng) - 0.5f, u(rng) - 0.5f);
      vk = test::window_vertex(p.x, p.y, 0.05f + 0.9f * u(rng), kW, kH, 0.5f + 1.5f * u(rng));
    }
    test::add_triangle(b, v[0], v[1], v[2]);
  }
  const OracleResult r = compare_with_embree(b, kW, kH);
  EXPECT_EQ(r.coverage_mismatches, 0);
  EXPECT_EQ(r.depth_mismatches, 0);
  EXPECT_GT(r.compared, kW * kH * 9 / 10);
  EXPECT_GT(r.covered, kW * kH / 2);
  record(r);
}

// A UV sphere of radius 1 at the origin, seen through view and projection.
TriangleBatch sphere(const glm::mat4& mvp, int slices, int stacks) {
  auto vertex = [&](int i, int j) {
    const float theta = 3.14159265f * float(j) / stacks,
                phi = 2.0f * 3.14159265f * float(i) / slices;
    ClipVertex v;
    v.position = mvp * glm::vec4(std::sin(theta) * std::cos(phi), std::cos(theta),
                                 std::sin(theta) * std::sin(phi), 1.0f);
    return v;
  };
  TriangleBatch b;
  for (int j = 0; j < stacks; ++j)
    for (int i = 0; i < slices; ++i) {
      const ClipVertex a = vertex(i, j), c = vertex(i + 1, j), d = vertex(i + 1, j + 1),
                       e = vertex(i, j + 1);
      if (j > 0) test::add_triangle(b, a, d, c);
      if (j + 1 < stacks) test::add_triangle(b, a, e, d);
    }
  return b;
}

TEST(RasterEmbreeOracle, TessellatedSphere) {
  constexpr int kW = 320, kH = 240;
  const glm::mat4 proj = glm::perspective(glm::radians(45.0f), float(kW) / kH, 0.1f, 20.0f);
  const glm::mat4 view =
      glm::lookAt(glm::vec3(0.4f, 0.7f, 3.2f), glm::vec3(0.0f), glm::vec3(0, 1, 0));
  const OracleResult r = compare_with_embree(sphere(proj * view, 96, 48), kW, kH);
  EXPECT_EQ(r.coverage_mismatches, 0);
  EXPECT_EQ(r.depth_mismatches, 0);
  EXPECT_GT(r.covered, 10000);
  record(r);
}

TEST(RasterEmbreeOracle, SphereCutByTheNearPlane) {
  // The eye just outside the sphere with a near plane reaching inside: the clipped pieces (and
  // the inside faces seen through the cut) must agree too.
  constexpr int kW = 320, kH = 240;
  // The near plane cuts a cap of radius about 0.7 off the sphere, inside the 90 degree view.
  const glm::mat4 proj = glm::perspective(glm::radians(90.0f), float(kW) / kH, 0.8f, 20.0f);
  const glm::mat4 view =
      glm::lookAt(glm::vec3(0.1f, 0.2f, 1.5f), glm::vec3(0.0f), glm::vec3(0, 1, 0));
  const TriangleBatch b = sphere(proj * view, 64, 32);
  Framebuffer probe(kW, kH);
  test::CountingProgram counter(kW, kH);
  const RasterStats s = draw_triangles(b, RasterState{}, counter, probe, Parallel(1));
  EXPECT_GT(s.triangles_rasterized, s.triangles_in - s.triangles_clipped_away);  // some were cut
  const OracleResult r = compare_with_embree(b, kW, kH);
  EXPECT_EQ(r.coverage_mismatches, 0);
  EXPECT_EQ(r.depth_mismatches, 0);
  EXPECT_GT(r.covered, 10000);
  record(r);
}

}  // namespace
}  // namespace tessref
