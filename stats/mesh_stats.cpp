#include "stats/mesh_stats.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace tessref::stats {
namespace {

enum class Shape { Convex, Concave, Inflection };

Shape edge_shape(const glm::vec3& na, const glm::vec3& nb, const glm::vec3& d) {
  const float sa = glm::dot(na, d), sb = glm::dot(nb, d);
  if (sa < 0.0f && sb > 0.0f) return Shape::Convex;
  if (sa > 0.0f && sb < 0.0f) return Shape::Concave;
  return Shape::Inflection;
}

void count(EdgeShapes& e, Shape s, double weight) {
  (s == Shape::Convex ? e.convex : s == Shape::Concave ? e.concave : e.inflection) += weight;
}

}  // namespace

MeshStats mesh_stats(const Mesh& m) {
  MeshStats s;
  s.vertices = m.vertex_count();
  s.triangles = m.triangle_count();
  std::vector<double> cosines;
  cosines.reserve(m.indices.size());
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edge_use;
  EdgeShapes half_edges;
  for (std::size_t t = 0; t < s.triangles; ++t) {
    const std::uint32_t* i = &m.indices[3 * t];
    const glm::vec3 &p0 = m.positions[i[0]], &p1 = m.positions[i[1]], &p2 = m.positions[i[2]];
    const glm::vec3 face = glm::normalize(glm::cross(p1 - p0, p2 - p0));
    for (int c = 0; c < 3; ++c) {
      cosines.push_back(double(glm::dot(m.normals[i[c]], face)));
      const std::uint32_t a = i[c], b = i[(c + 1) % 3];
      ++edge_use[std::minmax(a, b)];
      const glm::vec3 d = m.positions[b] - m.positions[a];
      count(half_edges, edge_shape(m.normals[a], m.normals[c == 2 ? a : b], d), 1.0);
    }
  }
  s.normal_cosine = summarize(cosines);
  s.seed004_shapes = {std::floor(half_edges.convex / 2), std::floor(half_edges.concave / 2),
                      std::floor(half_edges.inflection / 2)};
  s.edges = edge_use.size();
  for (const auto& [e, uses] : edge_use) {
    if (uses == 1) ++s.boundary_edges;
    if (uses > 2) ++s.nonmanifold_edges;
    count(s.shapes, edge_shape(m.normals[e.first], m.normals[e.second], m.positions[e.second] - m.positions[e.first]), 1.0);
  }
  return s;
}

}  // namespace tessref::stats
