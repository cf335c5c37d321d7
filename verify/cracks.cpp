#include "verify/cracks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <unordered_map>

namespace tessref {
namespace {

// One patch edge's tessellated boundary: the domain points on it, ordered from its first corner.
struct Boundary {
  std::uint32_t patch = 0;
  std::vector<double> t;  // 0 at the first corner, 1 at the second
  std::vector<std::uint32_t> point;  // the surface's points there
  std::vector<glm::dvec3> position;
  std::vector<glm::dvec3> face_normal;  // per segment: the geometric normal of its triangle

  // The segment s lies on, and the boundary's point there.
  std::size_t segment(double s) const {
    const std::size_t i = std::size_t(std::upper_bound(t.begin(), t.end(), s) - t.begin());
    return std::clamp<std::size_t>(i, 1, t.size() - 1) - 1;
  }
  glm::dvec3 at(double s) const {
    const std::size_t k = segment(s);
    return glm::mix(position[k], position[k + 1], std::clamp((s - t[k]) / (t[k + 1] - t[k]), 0.0, 1.0));
  }
};

std::uint64_t pair_key(std::uint32_t a, std::uint32_t b) {
  return std::uint64_t(std::min(a, b)) << 32 | std::max(a, b);
}

using Corner = std::array<std::uint32_t, 3>;  // a corner position's bits
Corner bits(const glm::vec3& p) {
  Corner c;
  std::memcpy(c.data(), &p.x, sizeof c);
  return c;
}

// Triangle domain edges as GL numbers gl_TessCoord (u weighs gl_in[0], v gl_in[1], w gl_in[2]):
// edge e lies where coordinate `zero` is 0 and runs from the corner where `from` is 1 to the one
// where `to` is 1; its parameter is the `to` coordinate.
struct DomainEdge {
  int zero, from, to;
};
constexpr DomainEdge kEdges[3] = {{2, 0, 1}, {0, 1, 2}, {1, 2, 0}};

}  // namespace

CrackReport find_cracks(const TessSurface& surface, const SurfaceOracle& oracle, const Parallel& parallel,
                        double standoff, double tolerance) {
  CrackReport report;
  const double diagonal = surface.diagonal();
  // Patches' points, patch by patch (a draw appends them in patch order; sort to be sure).
  std::vector<std::uint32_t> order(surface.points.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return surface.points[a].patch_id < surface.points[b].patch_id;
  });

  std::vector<Boundary> boundaries;
  std::map<std::pair<Corner, Corner>, std::vector<std::size_t>> edges;  // corners -> boundaries
  for (std::size_t i = 0; i < order.size();) {
    const std::uint32_t patch = surface.points[order[i]].patch_id;
    std::size_t end = i;
    while (end < order.size() && surface.points[order[end]].patch_id == patch) ++end;
    ++report.patches;
    for (std::size_t k = i; k < end; ++k) {
      const glm::vec3& c = surface.points[order[k]].tess_coord;
      if (std::fabs(double(c.x) + c.y + c.z - 1.0) > 1e-6) {
        report.triangles = false;
        return report;
      }
    }
    for (const DomainEdge& e : kEdges) {
      std::vector<std::pair<double, std::uint32_t>> on;
      for (std::size_t k = i; k < end; ++k) {
        const glm::vec3& c = surface.points[order[k]].tess_coord;
        if (c[e.zero] == 0.0f) on.emplace_back(c[e.to], order[k]);
      }
      std::sort(on.begin(), on.end());
      on.erase(std::unique(on.begin(), on.end(), [](const auto& a, const auto& b) { return a.first == b.first; }),
               on.end());
      if (on.size() < 2 || on.front().first != 0.0 || on.back().first != 1.0) continue;
      Boundary b;
      b.patch = patch;
      for (const auto& [t, p] : on) {
        b.t.push_back(t);
        b.point.push_back(p);
        b.position.emplace_back(surface.points[p].position);
      }
      Corner from = bits(surface.points[on.front().second].position), to = bits(surface.points[on.back().second].position);
      if (to < from) {  // one orientation per edge, whichever patch it comes from
        std::swap(from, to);
        std::reverse(b.t.begin(), b.t.end());
        for (double& t : b.t) t = 1.0 - t;
        std::reverse(b.point.begin(), b.point.end());
        std::reverse(b.position.begin(), b.position.end());
      }
      edges[{from, to}].push_back(boundaries.size());
      boundaries.push_back(std::move(b));
    }
    i = end;
  }

  // Each boundary segment's triangle, for its geometric normal: rays are aimed along the surface's
  // own normal (a file's stored normals may lie anywhere), and only from where both sides of the
  // edge face the ray the same way (at a fold the edge is a silhouette for the ray, and a ray
  // grazing it may miss both triangles without any gap).
  std::unordered_map<std::uint64_t, std::pair<std::uint32_t, std::uint32_t>> segments;  // -> boundary, segment
  for (std::size_t i = 0; i < boundaries.size(); ++i) {
    boundaries[i].face_normal.assign(boundaries[i].t.size() - 1, glm::dvec3(0.0));
    for (std::size_t k = 0; k + 1 < boundaries[i].t.size(); ++k)
      segments.emplace(pair_key(boundaries[i].point[k], boundaries[i].point[k + 1]),
                       std::pair(std::uint32_t(i), std::uint32_t(k)));
  }
  for (std::size_t t = 0; t < surface.triangle_count(); ++t)
    for (int e = 0; e < 3; ++e) {
      const auto it = segments.find(pair_key(surface.indices[3 * t + e], surface.indices[3 * t + (e + 1) % 3]));
      if (it == segments.end()) continue;
      const glm::dvec3 a(surface.corner(t, 0)), b(surface.corner(t, 1)), c(surface.corner(t, 2));
      const glm::dvec3 n = glm::cross(b - a, c - a);
      if (glm::dot(n, n) > 0.0) boundaries[it->second.first].face_normal[it->second.second] = glm::normalize(n);
    }

  std::vector<std::pair<std::size_t, std::size_t>> shared;
  for (const auto& [corners, list] : edges) {
    if (list.size() == 2)
      shared.emplace_back(list[0], list[1]);
    else
      ++report.unshared_edges;
  }
  report.shared_edges = shared.size();

  // Each shared edge in its own slot, merged in the map's order.
  std::vector<CrackReport::Edge> results(shared.size());
  std::vector<std::uint64_t> rays(shared.size()), grazing(shared.size());
  const double length = standoff * diagonal, slack = tolerance * diagonal;
  parallel.for_each(shared.size(), [&](std::size_t s) {
    const Boundary& a = boundaries[shared[s].first];
    const Boundary& b = boundaries[shared[s].second];
    CrackReport::Edge& r = results[s];
    r.patch_a = std::min(a.patch, b.patch), r.patch_b = std::max(a.patch, b.patch);
    r.from = glm::vec3(a.position.front()), r.to = glm::vec3(a.position.back());
    // The gap at every boundary vertex of either side; rays at the midpoints between them (not at
    // the corners, where more patches meet and a crack along another edge opens).
    std::vector<double> ts(a.t);
    ts.insert(ts.end(), b.t.begin(), b.t.end());
    std::sort(ts.begin(), ts.end());
    ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
    for (double t : ts) r.gap = std::max(r.gap, glm::length(a.at(t) - b.at(t)));
    const glm::dvec3 tangent = glm::normalize(a.position.back() - a.position.front());
    for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
      const double t = 0.5 * (ts[k] + ts[k + 1]);
      const glm::dvec3 pa = a.at(t), pb = b.at(t);
      r.gap = std::max(r.gap, glm::length(pa - pb));
      const glm::dvec3 aim = 0.5 * (pa + pb);
      const glm::dvec3 na = a.face_normal[a.segment(t)], nb = b.face_normal[b.segment(t)];
      const glm::dvec3 sum = na + nb;
      if (!(glm::dot(sum, sum) > 1e-6)) continue;  // a degenerate triangle, or a fold back onto itself
      const glm::dvec3 n = glm::normalize(sum);
      glm::dvec3 across = glm::cross(tangent, n);
      const bool tilt = glm::dot(across, across) > 1e-12;
      if (tilt) across = glm::normalize(across);
      // Along the normal and tilted 30 degrees either way across the edge, from both sides.
      for (double side : {1.0, -1.0})
        for (double sine : {0.0, 0.5, -0.5}) {
          if (sine != 0.0 && !tilt) continue;
          const glm::dvec3 dir = side * (std::sqrt(1.0 - sine * sine) * n + sine * across);
          const double da = glm::dot(dir, na), db = glm::dot(dir, nb);
          if (da * db <= 0.0 || std::min(std::fabs(da), std::fabs(db)) < 0.1) continue;
          ++rays[s];
          const SurfaceOracle::Hit h = oracle.cast(glm::vec3(aim - length * dir), glm::vec3(dir), 0.0f,
                                                   float(length + slack));
          // Where the two boundaries are the same points bit for bit there is no gap to pass
          // through: a miss there is the ray caster's own (a ray grazing a fold's edge in float).
          if (!h.hit()) ++(pa == pb ? grazing[s] : r.rays_through);
        }
    }
  });
  for (std::size_t s = 0; s < shared.size(); ++s) {
    report.rays += rays[s];
    report.grazing_misses += grazing[s];
    report.rays_through += results[s].rays_through;
    report.max_gap = std::max(report.max_gap, results[s].gap);
    if (results[s].rays_through) report.cracked.push_back(results[s]);
  }
  std::stable_sort(report.cracked.begin(), report.cracked.end(), [](const auto& x, const auto& y) {
    return x.gap > y.gap || (x.gap == y.gap && std::tie(x.patch_a, x.patch_b) < std::tie(y.patch_a, y.patch_b));
  });
  return report;
}

}  // namespace tessref
