#pragma once
// Embree 3 as an independent oracle for the rasterizer: the snapped window-space triangles the
// rasterizer sets up are handed to Embree, and one ray per pixel center, cast along +z, must find
// the same coverage and the same nearest window depth. Pixels whose center lies within 1e-4 pixel
// of any edge are left out: there the fill rule decides and a float ray test cannot.
// Used by tests/raster/embree_oracle_test.cpp and tests/pipeline/embree_default_scene_test.cpp.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <embree3/rtcore.h>
#include <gtest/gtest.h>

#include "raster/setup.h"
#include "raster_test_util.h"

namespace tessref::test {

constexpr double kEdgeExclusion = 1e-4;  // pixels
// Depth: Embree decides which triangle is nearest and its float t must agree with ours, but that
// t carries float rounding of order eps * (pixel coordinates * depth slope): measured up to
// 1.3e-5 relative on slivers, 2e-8 absolute near depth 0. So the 1e-5 relative bound is checked
// against the exact (double) depth of the triangle Embree found, and Embree's own t more loosely.
constexpr double kDepthTolerance = 1e-5;     // relative, against the exact plane depth
constexpr double kRayDepthTolerance = 1e-4;  // relative, against Embree's t ...
constexpr double kRayDepthAbsolute = 1e-7;   // ... plus this much absolute

// The set-up (clipped, snapped, wound) pieces of every triangle, exactly what is scanned.
inline std::vector<raster::SetupTriangle> setup_all(const TriangleBatch& batch, int w, int h,
                                                   bool cull_back_faces = false) {
  const raster::Viewport vp{w, h, 0.0f, 1.0f};
  std::vector<raster::SetupTriangle> tris;
  std::vector<float> varyings;
  for (std::size_t i = 0; i < batch.triangle_count(); ++i) {
    int pieces = 0;
    raster::setup_triangle(batch, i, vp, raster::FaceRule{false, cull_back_faces, false}, tris, varyings, pieces);
  }
  return tris;
}

// Depth of triangle t's plane at (px, py): the plane through its unsnapped window positions and
// depths (where llvmpipe, and so the rasterizer, fits it; SetupTriangle keeps it as barycentric
// planes), evaluated in double without the rasterizer's rounding to float and clamping.
inline double exact_depth_at(const raster::SetupTriangle& t, double px, double py) {
  const double dx = px - t.b_x0, dy = py - t.b_y0;
  const double b1 = t.b1_dx * dx + t.b1_dy * dy, b2 = t.b2_dx * dx + t.b2_dy * dy;
  return t.z[0] + b1 * (double(t.z[1]) - t.z[0]) + b2 * (double(t.z[2]) - t.z[0]);
}
inline double exact_depth(const raster::SetupTriangle& t, int x, int y) {
  return exact_depth_at(t, x + 0.5, y + 0.5);
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
        // Depth on the plane through the unsnapped positions (the rasterizer's, as llvmpipe's),
        // so that Embree's t is that plane's depth too.
        v[9 * t + 3 * k + 2] = float(exact_depth_at(tris[t], tris[t].x[k] / 256.0,
                                                    tris[t].y[k] / 256.0));
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
inline std::vector<char> near_edges(const std::vector<raster::SetupTriangle>& tris, int w, int h) {
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


struct OracleResult {
  int compared = 0, covered = 0, excluded = 0, coverage_mismatches = 0, depth_mismatches = 0;
  double worst_vs_exact = 0.0, worst_vs_ray = 0.0;  // relative depth differences
};

// Draws batch (culling as asked) and checks every pixel not near an edge against Embree.
inline OracleResult compare_with_embree(const TriangleBatch& batch, int w, int h,
                                        bool cull_back_faces = false) {
  Framebuffer fb(w, h);
  test::CountingProgram counter(w, h);  // any program: only coverage and depth are compared
  RasterState state;
  state.cull_back_faces = cull_back_faces;
  draw_triangles(batch, state, counter, fb, Parallel(2));
  const auto tris = setup_all(batch, w, h, cull_back_faces);
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

}  // namespace tessref::test
