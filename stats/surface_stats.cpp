#include "stats/surface_stats.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "mesh/reference_meshes.h"

namespace tessref::stats {

schemes::CubicNet<double> widen(const schemes::CubicNet<float>& f) {
  schemes::CubicNet<double> d;
  for (int k = 0; k < 10; ++k) d.b[k] = glm::dvec3(f.b[k]);
  return d;
}

double gaussian_curvature(const schemes::SurfacePoint<double>& s) {
  const glm::dvec3 c = glm::cross(s.du, s.dv);
  const double c2 = glm::dot(c, c);
  if (!(c2 > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  const glm::dvec3 n = c / std::sqrt(c2);
  const double L = glm::dot(s.duu, n), M = glm::dot(s.duv, n), N = glm::dot(s.dvv, n);
  // E G - F^2 = |du x dv|^2 (Lagrange's identity).
  return (L * N - M * M) / c2;
}

std::vector<glm::dvec2> triangle_grid(int segments, bool interior_only) {
  if (segments < (interior_only ? 3 : 1))
    throw std::invalid_argument("triangle_grid: " + std::to_string(segments) + " segments");
  std::vector<glm::dvec2> grid;
  for (int i = 0; i <= segments; ++i)
    for (int j = 0; i + j <= segments; ++j) {
      if (interior_only && (i == 0 || j == 0 || i + j == segments)) continue;
      grid.emplace_back(double(i) / segments, double(j) / segments);
    }
  return grid;
}

std::vector<schemes::CubicNet<float>> build_patches(const Mesh& m, Interpolant scheme,
                                                    const InterpolantParams& params) {
  std::vector<schemes::CubicNet<float>> nets(m.triangle_count());
  for (std::size_t t = 0; t < nets.size(); ++t) {
    const std::uint32_t* i = &m.indices[3 * t];
    const glm::vec3 p[3] = {m.positions[i[0]], m.positions[i[1]], m.positions[i[2]]};
    const glm::vec3 n[3] = {m.normals[i[0]], m.normals[i[1]], m.normals[i[2]]};
    nets[t] = schemes::cubic_net<float>(scheme, p, n, params);
  }
  return nets;
}

std::vector<double> distance_samples(const std::vector<schemes::CubicNet<float>>& patches,
                                     AnalyticSurface surface, int segments, const Parallel& parallel) {
  const std::vector<glm::dvec2> grid = triangle_grid(segments, false);
  std::vector<double> out(patches.size() * grid.size());
  parallel.for_each(patches.size(), [&](std::size_t p) {
    const schemes::CubicNet<double> net = widen(patches[p]);
    for (std::size_t g = 0; g < grid.size(); ++g) {
      // The position rounded from an exact evaluation of the float net, the distance in float.
      const glm::vec3 x(schemes::evaluate(net, grid[g].x, grid[g].y).position);
      const float d = surface == AnalyticSurface::UnitSphere ? seed004_sphere_distance(x)
                                                             : seed004_torus_distance(x);
      out[p * grid.size() + g] = double(d);
    }
  });
  return out;
}

std::vector<double> gaussian_curvature_samples(const std::vector<schemes::CubicNet<float>>& patches,
                                               int segments, const Parallel& parallel) {
  const std::vector<glm::dvec2> grid = triangle_grid(segments, true);
  std::vector<double> slots(patches.size() * grid.size());
  parallel.for_each(patches.size(), [&](std::size_t p) {
    const schemes::CubicNet<double> net = widen(patches[p]);
    for (std::size_t g = 0; g < grid.size(); ++g)
      slots[p * grid.size() + g] = gaussian_curvature(schemes::evaluate(net, grid[g].x, grid[g].y));
  });
  std::vector<double> out;
  out.reserve(slots.size());
  for (double k : slots)
    if (!std::isnan(k)) out.push_back(k);
  return out;
}

EdgeNormalCosines adjacent_normal_cosines(const Mesh& m,
                                          const std::vector<schemes::CubicNet<float>>& patches,
                                          int segments, const Parallel& parallel) {
  // Each edge's (triangle, corner where the edge starts) pairs, edges in vertex-pair order.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::pair<std::size_t, int>>> uses;
  for (std::size_t t = 0; t < m.triangle_count(); ++t)
    for (int c = 0; c < 3; ++c)
      uses[std::minmax(m.indices[3 * t + c], m.indices[3 * t + (c + 1) % 3])].emplace_back(t, c);
  struct SharedEdge {
    std::uint32_t from;
    std::pair<std::size_t, int> side[2];
  };
  std::vector<SharedEdge> edges;
  EdgeNormalCosines r;
  for (const auto& [e, u] : uses) {
    if (u.size() != 2) {
      ++r.edges_skipped;
      continue;
    }
    edges.push_back({e.first, {u[0], u[1]}});
  }
  r.edges_sampled = edges.size();
  const std::size_t per_edge = std::size_t(segments) + 1;
  std::vector<double> slots(edges.size() * per_edge);
  parallel.for_each(edges.size(), [&](std::size_t e) {
    const SharedEdge& edge = edges[e];
    schemes::CubicNet<double> nets[2] = {widen(patches[edge.side[0].first]), widen(patches[edge.side[1].first])};
    for (std::size_t k = 0; k < per_edge; ++k) {
      const double t = double(k) / segments;  // 0 at edge.from
      glm::dvec3 normal[2];
      for (int s = 0; s < 2; ++s) {
        const auto [tri, corner] = edge.side[s];
        const int next = (corner + 1) % 3;
        double w[3] = {0.0, 0.0, 0.0};
        const bool forward = m.indices[3 * tri + corner] == edge.from;
        w[corner] = forward ? 1.0 - t : t;
        w[next] = forward ? t : 1.0 - t;
        normal[s] = schemes::analytic_normal(schemes::evaluate(nets[s], w[1], w[2]));
      }
      const bool ok = glm::dot(normal[0], normal[0]) > 0.0 && glm::dot(normal[1], normal[1]) > 0.0;
      slots[e * per_edge + k] = ok ? glm::dot(normal[0], normal[1]) : std::numeric_limits<double>::quiet_NaN();
    }
  });
  r.cosines.reserve(slots.size());
  for (double c : slots) {
    if (std::isnan(c))
      ++r.degenerate_points;
    else
      r.cosines.push_back(c);
  }
  return r;
}

}  // namespace tessref::stats
