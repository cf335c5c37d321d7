// Seed 004's meshes as generated: counts, orientation, normals, and their names in scenes.
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include <gtest/gtest.h>

#include "common/error.h"
#include "mesh/mesh_source.h"
#include "mesh/procedural.h"
#include "mesh/reference_meshes.h"
#include "scene/scene_loader.h"
#include "stats/summary.h"

namespace tessref {
namespace {

std::size_t edge_count(const Mesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> e;
  for (std::size_t t = 0; t < m.indices.size(); t += 3)
    for (int c = 0; c < 3; ++c) ++e[std::minmax(m.indices[t + c], m.indices[t + (c + 1) % 3])];
  return e.size();
}

// Every face normal agrees with its corners' normals: counter-clockwise seen from outside.
void expect_outward(const Mesh& m) {
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    const std::uint32_t* i = &m.indices[3 * t];
    const glm::vec3 f = glm::cross(m.positions[i[1]] - m.positions[i[0]], m.positions[i[2]] - m.positions[i[0]]);
    EXPECT_GT(glm::dot(f, m.normals[i[0]] + m.normals[i[1]] + m.normals[i[2]]), 0.0f) << "triangle " << t;
  }
}

struct Counts {
  std::size_t vertices, triangles, edges;
};

void expect_counts_and_outward(const Mesh& m, const Counts& want) {
  EXPECT_EQ(m.vertex_count(), want.vertices);
  EXPECT_EQ(m.triangle_count(), want.triangles);
  EXPECT_EQ(edge_count(m), want.edges);
  expect_outward(m);
}

TEST(ReferenceMeshes, SphereCountsForEveryRefinement) {
  for (int i = 0; i <= 3; ++i) {
    const Mesh m = make_icosphere(i, 1.0f);
    EXPECT_EQ(m.triangle_count(), 20u << (2 * i));
    EXPECT_EQ(m.vertex_count(), 10u * (1u << (2 * i)) + 2u);
    for (std::size_t v = 0; v < m.vertex_count(); ++v) EXPECT_NEAR(glm::length(m.positions[v]), 1.0f, 2e-7f);
  }
}

TEST(ReferenceMeshes, TorusGridFromTheInnerEquator) {
  for (int j : {3, 5, 10, 19}) {
    const Mesh m = make_seed004_torus(j);
    const std::size_t n = std::size_t(j * j);
    expect_counts_and_outward(m, {.vertices = n, .triangles = 2 * n, .edges = 3 * n});
    for (const glm::vec3& p : m.positions) EXPECT_NEAR(seed004_torus_distance(p), 0.0f, 2e-7f);
  }
  // Vertex 0 at u = 0, v = pi: the inner equator, 0.5 from the axis.
  const Mesh m = make_seed004_torus(5);
  EXPECT_NEAR(m.positions[0].x, 0.5f, 1e-7f);
  EXPECT_NEAR(m.positions[0].y, 0.0f, 1e-7f);
}

TEST(ReferenceMeshes, TorusNormalsAnalyticOrFaceAverages) {
  const Mesh analytic = make_seed004_torus(10, ReferenceNormals::Analytic);
  const Mesh averaged = make_seed004_torus(10);
  double worst = 1.0;
  for (std::size_t v = 0; v < analytic.vertex_count(); ++v) {
    // The analytic normal points from the tube's centre circle to the vertex.
    const glm::vec3 p = analytic.positions[v];
    const glm::vec3 centre = glm::normalize(glm::vec3(p.x, 0.0f, p.z));
    EXPECT_NEAR(glm::length(analytic.normals[v] - 2.0f * (p - centre)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(averaged.normals[v]), 1.0f, 1e-6f);
    worst = std::min(worst, double(glm::dot(analytic.normals[v], averaged.normals[v])));
  }
  // The averages lean: the diagonals make the six faces around a vertex asymmetric.
  EXPECT_LT(worst, 0.9999);
  EXPECT_GT(worst, 0.99);
}

TEST(ReferenceMeshes, FaceAverageIsTheUnweightedMean) {
  // A vertex with one big and one small face at right angles: the mean lies at 45 degrees.
  const std::vector<glm::vec3> p = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {0, 0, 1}, {0, 1, 0}};
  const std::vector<std::uint32_t> idx = {0, 1, 2, 0, 3, 4};
  const std::vector<glm::vec3> n = face_average_normals(p, idx);
  EXPECT_NEAR(n[0].x, -std::sqrt(0.5f), 1e-6f);
  EXPECT_NEAR(n[0].z, std::sqrt(0.5f), 1e-6f);
}

TEST(ReferenceMeshes, RoundedCube) {
  const Mesh m = make_rounded_cube();
  expect_counts_and_outward(m, {.vertices = 30, .triangles = 56, .edges = 84});
  EXPECT_THROW(make_rounded_cube(1.0f), std::invalid_argument);
  float extent = 0.0f;
  for (const glm::vec3& p : m.positions) extent = std::max(extent, p.x);
  EXPECT_EQ(extent, 0.68f);
}

TEST(ReferenceMeshes, Vase) {
  expect_counts_and_outward(make_seed004_vase(), {.vertices = 241, .triangles = 460, .edges = 700});
}

TEST(ReferenceMeshes, NamedInScenes) {
  std::vector<std::string> warnings;
  Scene s = load_scene("", {"mesh.type=seed004_torus"});
  EXPECT_EQ(build_mesh(s.mesh, warnings).triangle_count(), 200u);
  s = load_scene("", {"mesh.type=seed004_torus", "mesh.seed004_torus={\"grid\": 5, \"normals\": \"analytic\"}"});
  EXPECT_EQ(s.mesh.seed004_torus_grid, 5);
  EXPECT_TRUE(s.mesh.seed004_torus_analytic_normals);
  EXPECT_EQ(build_mesh(s.mesh, warnings).triangle_count(), 50u);
  s = load_scene("", {"mesh.type=rounded_cube", "mesh.rounded_cube={\"cut\": 0.25, \"half_size\": 2}"});
  EXPECT_EQ(s.mesh.rounded_cube_cut, 0.25f);
  EXPECT_EQ(s.mesh.rounded_cube_half_size, 2.0f);
  EXPECT_EQ(build_mesh(s.mesh, warnings).triangle_count(), 56u);
  s = load_scene("", {"mesh.type=vase"});
  EXPECT_EQ(build_mesh(s.mesh, warnings).triangle_count(), 460u);
  EXPECT_TRUE(warnings.empty());
  EXPECT_THROW(load_scene("", {"mesh.type=seed004_torus", "mesh.seed004_torus={\"grid\": 2}"}), InputError);
  EXPECT_THROW(load_scene("", {"mesh.type=seed004_torus", "mesh.seed004_torus={\"normals\": \"radial\"}"}), InputError);
  EXPECT_THROW(load_scene("", {"mesh.type=rounded_cube", "mesh.rounded_cube={\"cut\": 1}"}), InputError);
}

}  // namespace
}  // namespace tessref
