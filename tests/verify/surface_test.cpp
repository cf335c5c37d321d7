// The Embree oracle that verify measures with: closest points against brute force, rays and the
// back-face filter, distances between known surfaces, and the crack finder on tessref's own
// tessellations (seed 000: shared normals are watertight at every level and spacing).
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "mesh/camera.h"
#include "mesh/mesh_source.h"
#include "render/render.h"
#include "scene/scene_loader.h"
#include "../pipeline/test_util.h"
#include "split_cylinder.h"
#include "verify/cracks.h"
#include "verify/surface.h"
#include "verify/surface_distance.h"

namespace tessref {
namespace {

// A w x h grid of unit squares in the plane z = `z`, two triangles each, one patch per square.
TessSurface grid(int w, int h, float z) {
  TessSurface s;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const auto patch = std::uint32_t(y * w + x);
      const glm::vec3 p[4] = {{x, y, z}, {x + 1, y, z}, {x + 1, y + 1, z}, {x, y + 1, z}};
      for (int k : {0, 1, 2, 0, 2, 3}) {
        s.indices.push_back(std::uint32_t(s.points.size()));
        s.points.push_back({patch, glm::vec3(0.0f), p[k], glm::vec3(0, 0, 1)});
      }
    }
  return s;
}

TEST(SurfaceOracle, ClosestPointsEqualBruteForce) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-2.0f, 2.0f);
  TessSurface s;
  for (int t = 0; t < 40; ++t)
    for (int k = 0; k < 3; ++k) {
      s.indices.push_back(std::uint32_t(s.points.size()));
      s.points.push_back({std::uint32_t(t), glm::vec3(0.0f), glm::vec3(u(rng), u(rng), u(rng)), glm::vec3(0.0f)});
    }
  const SurfaceOracle oracle(s);
  for (int i = 0; i < 500; ++i) {
    const glm::vec3 p(u(rng), u(rng), u(rng));
    double best = INFINITY;
    for (std::size_t t = 0; t < s.triangle_count(); ++t)
      best = std::min(best, glm::length(closest_point_on_triangle(p, s.corner(t, 0), s.corner(t, 1), s.corner(t, 2)) -
                                        glm::dvec3(p)));
    EXPECT_EQ(oracle.closest(p).distance, best) << i;
  }
}

TEST(SurfaceOracle, ClosestPointOnTriangleByRegion) {
  const glm::dvec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_EQ(closest_point_on_triangle({0.25, 0.25, 3}, a, b, c), glm::dvec3(0.25, 0.25, 0));  // face
  EXPECT_EQ(closest_point_on_triangle({0.5, -1, 0}, a, b, c), glm::dvec3(0.5, 0, 0));         // edge ab
  EXPECT_EQ(closest_point_on_triangle({-1, -1, 1}, a, b, c), a);                              // corner
  EXPECT_EQ(closest_point_on_triangle({2, 2, 0}, a, b, c), glm::dvec3(0.5, 0.5, 0));          // edge bc
  // A degenerate triangle (a segment) still answers.
  EXPECT_EQ(closest_point_on_triangle({0.5, 1, 0}, a, b, b), glm::dvec3(0.5, 0, 0));
}

TEST(SurfaceOracle, RaysHitAndBackFacesAreCulledOnRequest) {
  const TessSurface s = grid(2, 2, 0.0f);  // counter-clockwise seen from +z
  const SurfaceOracle oracle(s);
  SurfaceOracle::Hit h = oracle.cast({0.5f, 0.5f, 1.0f}, {0, 0, -1}, 0.0f, 10.0f);
  ASSERT_TRUE(h.hit());
  EXPECT_EQ(h.t, 1.0f);
  EXPECT_TRUE(oracle.cast({0.5f, 0.5f, 1.0f}, {0, 0, -1}, 0.0f, 10.0f, true).hit());    // front face
  EXPECT_TRUE(oracle.cast({0.5f, 0.5f, -1.0f}, {0, 0, 1}, 0.0f, 10.0f).hit());
  EXPECT_FALSE(oracle.cast({0.5f, 0.5f, -1.0f}, {0, 0, 1}, 0.0f, 10.0f, true).hit());  // back face
  EXPECT_FALSE(oracle.cast({3.5f, 0.5f, 1.0f}, {0, 0, -1}, 0.0f, 10.0f).hit());        // beside it
  // Watertight: a ray exactly through the shared vertex in the middle hits.
  EXPECT_TRUE(oracle.cast({1.0f, 1.0f, 1.0f}, {0, 0, -1}, 0.0f, 10.0f).hit());
}

TEST(SurfaceDistance, ParallelPlanesAreTheirSeparationApart) {
  const TessSurface a = grid(4, 4, 0.0f), b = grid(4, 4, 0.25f);
  const SurfaceOracle oa(a), ob(b);
  const SurfaceDistance d = surface_distance(a, oa, b, ob, Parallel(2));
  EXPECT_EQ(d.hausdorff, 0.25);
  EXPECT_EQ(d.reference_to_tessref.rms, 0.25);
  EXPECT_EQ(d.reference_to_tessref.samples, 16u * 4u);  // 4 distinct corners in each of 16 patches
  const SurfaceDistance same = surface_distance(a, oa, a, oa, Parallel(2));
  EXPECT_EQ(same.hausdorff, 0.0);
  // One patch lifted: it is the worst, by its lift.
  TessSurface lifted = a;
  for (TessDumpRecord& r : lifted.points)
    if (r.patch_id == 9) r.position.z += 0.5f;
  const SurfaceOracle ol(lifted);
  const SurfaceDistance one = surface_distance(a, oa, lifted, ol, Parallel(3));
  EXPECT_EQ(one.worst_patches.at(0).first, 9u);
  EXPECT_EQ(one.worst_patches.at(0).second, 0.5);
  // The thread count changes nothing.
  const SurfaceDistance serial = surface_distance(a, oa, lifted, ol, Parallel(1));
  EXPECT_EQ(serial.reference_to_tessref.rms, one.reference_to_tessref.rms);
  EXPECT_EQ(serial.tessref_to_reference.rms, one.tessref_to_reference.rms);
}

TessSurface tessellated(const std::vector<std::string>& sets) {
  Scene scene = load_scene("", sets);
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  TessSurface s;
  DrawOptions options;
  options.tess_surface = [&](const std::vector<TessDumpRecord>& r, const TriangleBatch& b) { s.append(r, b); };
  render_scene(scene, mesh, Parallel(2), options);
  return s;
}

// Seed 000: with one normal per vertex both patches along an edge evaluate the same curve, bit
// for bit in tessref, so no ray finds a gap, at any level and spacing.
TEST(Cracks, NoneWithSharedNormalsAtAnyLevelOrSpacing) {
  for (const char* mesh : {"torus", "icosphere", "cube"})
    for (const char* spacing : {"equal", "fractional_odd", "fractional_even"})
      for (const char* level : {"1", "1.5", "2", "3.3", "7", "12.7", "33", "64"}) {
        SCOPED_TRACE(std::string(mesh) + " " + spacing + " " + level);
        const TessSurface s = tessellated({"mesh.type=" + std::string(mesh), "image.width=16", "image.height=16",
                                           "tessellation.spacing=" + std::string(spacing),
                                           "tessellation.inner=" + std::string(level),
                                           "tessellation.outer=" + std::string(level)});
        const SurfaceOracle oracle(s);
        const CrackReport c = find_cracks(s, oracle, Parallel(2));
        EXPECT_TRUE(c.triangles);
        EXPECT_GT(c.shared_edges, 0u);
        EXPECT_EQ(c.unshared_edges, 0u);  // closed meshes
        EXPECT_EQ(c.max_gap, 0.0);
        EXPECT_EQ(c.rays_through, 0u);
      }
}

TEST(Cracks, SplitNormalsOpenTheRimAndNothingElse) {
  test::TempDir dir;
  dir.write("cylinder.obj", test::split_cylinder_obj());
  for (const char* level : {"2", "5", "12.7"}) {
    SCOPED_TRACE(level);
    const TessSurface s = tessellated({"mesh.type=file", "mesh.path=" + (dir.path() / "cylinder.obj").string(),
                                       "mesh.normals=split", "image.width=16", "image.height=16",
                                       "tessellation.inner=" + std::string(level),
                                       "tessellation.outer=" + std::string(level)});
    const SurfaceOracle oracle(s);
    const CrackReport c = find_cracks(s, oracle, Parallel(2));
    EXPECT_EQ(c.shared_edges, 72u);
    ASSERT_EQ(c.cracked.size(), 24u);
    for (const CrackReport::Edge& e : c.cracked) {
      EXPECT_LT(e.patch_a % 4, 2u);   // a side patch
      EXPECT_GE(e.patch_b % 4, 2u);   // against a cap
      EXPECT_EQ(e.patch_a / 4, e.patch_b / 4);
      EXPECT_GT(e.gap, 1e-3);
    }
  }
}

}  // namespace
}  // namespace tessref
