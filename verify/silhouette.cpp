#include "verify/silhouette.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "common/hash.h"

namespace tessref {
namespace {

struct Segment {
  glm::dvec2 a, b;  // pixels, x right, y down, pixel centres at +0.5
};

double distance_to_segment(const glm::dvec2& p, const Segment& s) {
  const glm::dvec2 ab = s.b - s.a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(glm::dot(p - s.a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - (s.a + t * ab));
}

// The silhouette in screen space. Vertices are joined by position (patches do not share records),
// so an edge two patches share is one edge.
std::vector<Segment> silhouette_segments(const TessSurface& s, const glm::dmat4& vp, int w, int h) {
  std::unordered_map<FloatBits3, std::uint32_t, FloatBits3::Hash> ids;
  std::vector<glm::dvec4> clip;
  std::vector<std::uint32_t> welded(s.points.size());
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const glm::vec3& p = s.points[i].position;
    auto [it, added] = ids.emplace(FloatBits3(&p.x), std::uint32_t(clip.size()));
    if (added) clip.push_back(vp * glm::dvec4(glm::dvec3(p), 1.0));
    welded[i] = it->second;
  }
  const auto screen = [&](std::uint32_t v) {
    const glm::dvec4& c = clip[v];
    return glm::dvec2((c.x / c.w + 1.0) * 0.5 * w, (1.0 - c.y / c.w) * 0.5 * h);
  };
  // Per edge: how many triangles face the camera and how many face away.
  struct Faces {
    int front = 0, back = 0;
  };
  std::unordered_map<std::uint64_t, Faces> edges;
  for (std::size_t t = 0; t < s.triangle_count(); ++t) {
    std::uint32_t v[3];
    bool visible = true;
    for (int k = 0; k < 3; ++k) v[k] = welded[s.indices[3 * t + k]], visible &= clip[v[k]].w > 0.0;
    if (!visible) continue;
    const glm::dvec2 a = screen(v[0]), b = screen(v[1]), c = screen(v[2]);
    const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t p = std::min(v[k], v[(k + 1) % 3]), q = std::max(v[k], v[(k + 1) % 3]);
      if (p == q) continue;
      Faces& f = edges[std::uint64_t(p) << 32 | q];
      (area >= 0.0 ? f.front : f.back) += 1;
    }
  }
  std::vector<Segment> out;
  for (const auto& [key, f] : edges)
    if (f.front + f.back == 1 || (f.front > 0 && f.back > 0) || f.front + f.back > 2)
      out.push_back({screen(std::uint32_t(key >> 32)), screen(std::uint32_t(key))});
  // Hash order is not fixed; the distances are minima, so order does not change them, but sort
  // anyway so that every run walks the same list.
  std::sort(out.begin(), out.end(), [](const Segment& x, const Segment& y) {
    return std::tie(x.a.x, x.a.y, x.b.x, x.b.y) < std::tie(y.a.x, y.a.y, y.b.x, y.b.y);
  });
  return out;
}

std::size_t bucket(double d) {
  if (d <= 0.5) return 0;
  if (d <= 1.0) return 1;
  if (d <= 2.0) return 2;
  if (d <= 4.0) return 3;
  if (d <= 8.0) return 4;
  return 5;
}

}  // namespace

SilhouetteComparison compare_silhouette(const FloatImage& reference_depth, const TessSurface& surface,
                                        const SurfaceOracle& oracle, const glm::mat4& view_projection,
                                        bool cull_back, const Parallel& parallel) {
  const int w = reference_depth.width, h = reference_depth.height;
  const glm::dmat4 vp(view_projection);
  const glm::dmat4 inv = glm::inverse(vp);
  SilhouetteComparison c;
  c.pixels = std::uint64_t(w) * h;
  std::vector<char> hit(c.pixels);
  parallel.for_each(std::size_t(h), [&](std::size_t y) {
    for (int x = 0; x < w; ++x) {
      // The pixel centre's ray from the near plane to the far plane (NDC z = -1 .. 1).
      const double nx = 2.0 * (x + 0.5) / w - 1.0, ny = 1.0 - 2.0 * (double(y) + 0.5) / h;
      const glm::dvec4 n = inv * glm::dvec4(nx, ny, -1.0, 1.0), f = inv * glm::dvec4(nx, ny, 1.0, 1.0);
      const glm::dvec3 near = glm::dvec3(n) / n.w, far = glm::dvec3(f) / f.w;
      hit[y * std::size_t(w) + x] = oracle.cast(glm::vec3(near), glm::vec3(far - near), 0.0f, 1.0f, cull_back).hit();
    }
  });
  std::vector<std::size_t> mismatches;
  for (std::size_t i = 0; i < c.pixels; ++i) {
    const bool theirs = reference_depth.pixels[i] < 1.0f;
    c.covered_reference += theirs;
    c.covered_rays += hit[i];
    if (theirs != bool(hit[i])) mismatches.push_back(i);
  }
  c.mismatched = mismatches.size();
  c.distance.assign(c.pixels, -1.0f);
  if (mismatches.empty()) return c;

  const std::vector<Segment> segments = silhouette_segments(surface, vp, w, h);
  c.silhouette_edges = segments.size();
  std::vector<double> d(mismatches.size(), INFINITY);
  parallel.for_each(mismatches.size(), [&](std::size_t m) {
    const glm::dvec2 p(double(mismatches[m] % w) + 0.5, double(mismatches[m] / w) + 0.5);
    for (const Segment& s : segments) d[m] = std::min(d[m], distance_to_segment(p, s));
  });
  std::vector<std::size_t> order(mismatches.size());
  for (std::size_t m = 0; m < mismatches.size(); ++m) {
    order[m] = m;
    const double dm = std::isinf(d[m]) ? double(w + h) : d[m];  // no silhouette at all: far
    c.distance[mismatches[m]] = float(dm);
    c.beyond_half_pixel += dm > 0.5;
    c.max_distance = std::max(c.max_distance, dm);
    ++c.by_distance[bucket(dm)];
  }
  const std::size_t k = std::min<std::size_t>(10, order.size());
  std::partial_sort(order.begin(), order.begin() + k, order.end(),
                    [&](std::size_t a, std::size_t b) { return d[a] > d[b] || (d[a] == d[b] && a < b); });
  for (std::size_t m = 0; m < k; ++m)
    c.worst_pixels.push_back({int(mismatches[order[m]] % w), int(mismatches[order[m]] / w)});
  return c;
}

}  // namespace tessref
