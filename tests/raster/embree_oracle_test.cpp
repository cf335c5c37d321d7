// Embree 3 as an independent oracle: the snapped window-space triangles the rasterizer sets up are
// handed to Embree, and one ray per pixel center, cast along +z, must find the same coverage and
// the same nearest window depth. Pixels whose center lies within 1e-4 pixel of any edge are left
// out: there the fill rule decides and a float ray test cannot.
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <embree3/rtcore.h>
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "raster/setup.h"
#include "raster_test_util.h"

namespace tessref {
namespace {

constexpr double kEdgeExclusion = 1e-4;  // pixels
// Depth: Embree decides which triangle is nearest and its float t must agree with ours, but that
// t carries float rounding of order eps * (pixel coordinates * depth slope): measured up to
// 1.3e-5 relative on slivers, 2e-8 absolute near depth 0. So the 1e-5 relative bound is checked
// against the exact (double) depth of the triangle Embree found, and Embree's own t more loosely.
constexpr double kDepthTolerance = 1e-5;     // relative, against the exact plane depth
constexpr double kRayDepthTolerance = 1e-4;  // relative, against Embree's t ...
constexpr double kRayDepthAbsolute = 1e-7;   // ... plus this much absolute

// The set-up (clipped, snapped, wound) pieces of every triangle, exactly what is scanned.
std::vector<raster::SetupTriangle> setup_all(const TriangleBatch& batch, int w, int h) {
  const raster::Viewport vp{w, h, 0.0f, 1.0f};
  std::vector<raster::SetupTriangle> tris;
  std::vector<float> varyings;
  for (std::size_t i = 0; i < batch.triangle_count(); ++i) {
    int pieces = 0;
    raster::setup_triangle(batch, i, vp, false, tris, varyings, pieces);
  }
  return tris;
}

class EmbreeOracle {
 public:
  explicit EmbreeOracle(const std::vector<raster::SetupTriangle>& tris) {
    device_ = rtcNewDevice(nullptr);
    scene_ = rtcNewScene(device_);
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * tris.size()));
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), tris.size()));
    for (std::size_t t = 0; t < tris.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        // 24.8 -> pixels is exact in float (at most 22 significant bits).
        v[9 * t + 3 * k + 0] = float(tris[t].x[k]) / 256.0f;
        v[9 * t + 3 * k + 1] = float(tris[t].y[k]) / 256.0f;
        v[9 * t + 3 * k + 2] = tris[t].z[k];
        idx[3 * t + k] = unsigned(3 * t + k);
      }
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene_, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(scene_);
  }
  ~EmbreeOracle() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }
  struct Hit {
    float t;        // +inf on a miss
    unsigned prim;  // index of the nearest triangle
  };
  // Nearest hit along the ray from (x + 0.5, y + 0.5, 0) toward +z: t is the window depth.
  Hit intersect(int x, int y) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRayHit rh{};
    rh.ray.org_x = float(x) + 0.5f;
    rh.ray.org_y = float(y) + 0.5f;
    rh.ray.org_z = 0.0f;
    rh.ray.dir_x = 0.0f;
    rh.ray.dir_y = 0.0f;
    rh.ray.dir_z = 1.0f;
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = std::numeric_limits<float>::infinity();
    rh.ray.mask = ~0u;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &ctx, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID)
      return {std::numeric_limits<float>::infinity(), 0};
    return {rh.ray.tfar, rh.hit.primID};
  }

 private:
  RTCDevice device_;
  RTCScene scene_;
};

// Marks pixels whose center is within kEdgeExclusion of an edge of any triangle.
std::vector<char> near_edges(const std::vector<raster::SetupTriangle>& tris, int w, int h) {
  std::vector<char> mark(std::size_t(w) * h, 0);
  for (const auto& t : tris) {
    for (int k = 0; k < 3; ++k) {
      const glm::dvec2 a(t.x[k] / 256.0, t.y[k] / 256.0);
      const glm::dvec2 b(t.x[(k + 1) % 3] / 256.0, t.y[(k + 1) % 3] / 256.0);
      const int x0 = std::max(0, int(std::floor(std::min(a.x, b.x) - 1)));
      const int x1 = std::min(w - 1, int(std::ceil(std::max(a.x, b.x) + 1)));
      const int y0 = std::max(0, int(std::floor(std::min(a.y, b.y) - 1)));
      const int y1 = std::min(h - 1, int(std::ceil(std::max(a.y, b.y) + 1)));
      const glm::dvec2 e = b - a;
      const double len2 = glm::dot(e, e);
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
          const glm::dvec2 p(x + 0.5, y + 0.5);
          const double s = len2 > 0 ? std::clamp(glm::dot(p - a, e) / len2, 0.0, 1.0) : 0.0;
          if (glm::length(p - (a + s * e)) < kEdgeExclusion) mark[std::size_t(y) * w + x] = 1;
        }
    }
  }
  return mark;
}

// Depth of triangle t at the center of pixel (x, y), by barycentrics in double from its snapped
// vertices (an independent evaluation of the same plane).
double exact_depth(const raster::SetupTriangle& t, int x, int y) {
  const double px = x + 0.5, py = y + 0.5;
  double e[3];
  for (int k = 0; k < 3; ++k) {
    const int a = (k + 1) % 3, b = (k + 2) % 3;
    const double ax = t.x[a] / 256.0, ay = t.y[a] / 256.0, bx = t.x[b] / 256.0, by = t.y[b] / 256.0;
    e[k] = (bx - ax) * (py - ay) - (by - ay) * (px - ax);
  }
  return (e[0] * t.z[0] + e[1] * t.z[1] + e[2] * t.z[2]) / (e[0] + e[1] + e[2]);
}

struct OracleResult {
  int compared = 0, covered = 0, excluded = 0, coverage_mismatches = 0, depth_mismatches = 0;
  double worst_vs_exact = 0.0, worst_vs_ray = 0.0;  // relative depth differences
};

OracleResult compare_with_embree(const TriangleBatch& batch, int w, int h) {
  Framebuffer fb(w, h);
  test::CountingProgram counter(w, h);  // any program: only coverage and depth are compared
  draw_triangles(batch, RasterState{}, counter, fb, Parallel(2));
  const auto tris = setup_all(batch, w, h);
  const EmbreeOracle oracle(tris);
  const auto excluded = near_edges(tris, w, h);
  OracleResult r;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = fb.index(x, y);
      if (excluded[i]) {
        ++r.excluded;
        continue;
      }
      ++r.compared;
      const EmbreeOracle::Hit hit = oracle.intersect(x, y);
      const bool ray_hit = std::isfinite(hit.t);
      const bool raster_hit = fb.depth[i] < 1.0f;
      if (ray_hit != raster_hit) {
        if (++r.coverage_mismatches <= 5)
          ADD_FAILURE() << "coverage at " << x << "," << y << ": raster " << raster_hit << " ray "
                        << ray_hit;
        continue;
      }
      if (!ray_hit) continue;
      ++r.covered;
      const double raster = fb.depth[i];
      const double exact = exact_depth(tris[hit.prim], x, y);
      const double rel_exact = std::abs(raster - exact) / exact;
      const double rel_ray = std::max(0.0, std::abs(raster - hit.t) - kRayDepthAbsolute) / exact;
      r.worst_vs_exact = std::max(r.worst_vs_exact, rel_exact);
      r.worst_vs_ray = std::max(r.worst_vs_ray, rel_ray);
      if (rel_exact > kDepthTolerance || rel_ray > kRayDepthTolerance) {
        if (++r.depth_mismatches <= 5)
          ADD_FAILURE() << "depth at " << x << "," << y << ": raster " << raster << " embree t "
                        << hit.t << " exact depth of embree's triangle " << exact;
      }
    }
  return r;
}

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
