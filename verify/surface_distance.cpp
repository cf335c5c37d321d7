#include "verify/surface_distance.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>

namespace tessref {
namespace {

// The vertices the triangles use, once per (patch, position): a captured stream repeats each
// vertex for every triangle that uses it.
std::vector<std::uint32_t> distinct_vertices(const TessSurface& s, const std::function<bool(std::uint32_t)>& patches) {
  std::vector<std::uint32_t> v(s.indices);
  if (patches) std::erase_if(v, [&](std::uint32_t i) { return !patches(s.points[i].patch_id); });
  const auto key = [&](std::uint32_t i) {
    const TessDumpRecord& r = s.points[i];
    return std::tuple(r.patch_id, std::bit_cast<std::uint32_t>(r.position.x), std::bit_cast<std::uint32_t>(r.position.y),
                      std::bit_cast<std::uint32_t>(r.position.z));
  };
  std::sort(v.begin(), v.end(), [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b) || (key(a) == key(b) && a < b); });
  v.erase(std::unique(v.begin(), v.end(), [&](std::uint32_t a, std::uint32_t b) { return key(a) == key(b); }), v.end());
  return v;
}

// One direction: every distinct vertex of `from` to the surface of `to`. Chunks write their own
// slots, merged in order, so the sums do not depend on the thread count.
SurfaceDistance::Side one_side(const TessSurface& from, const SurfaceOracle& to, const Parallel& parallel,
                               std::map<std::uint32_t, double>& per_patch,
                               const std::function<bool(std::uint32_t)>& patches) {
  const std::vector<std::uint32_t> vertices = distinct_vertices(from, patches);
  std::vector<double> distance(vertices.size());
  constexpr std::size_t kChunk = 4096;
  parallel.for_each((vertices.size() + kChunk - 1) / kChunk, [&](std::size_t c) {
    for (std::size_t i = c * kChunk; i < std::min(vertices.size(), (c + 1) * kChunk); ++i)
      distance[i] = to.closest(from.points[vertices[i]].position).distance;
  });
  SurfaceDistance::Side side;
  side.samples = vertices.size();
  double squares = 0.0;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const std::uint32_t patch = from.points[vertices[i]].patch_id;
    squares += distance[i] * distance[i];
    if (distance[i] > side.max || side.worst_patch < 0) side.max = distance[i], side.worst_patch = patch;
    double& m = per_patch[patch];
    m = std::max(m, distance[i]);
  }
  side.rms = vertices.empty() ? 0.0 : std::sqrt(squares / double(vertices.size()));
  return side;
}

}  // namespace

SurfaceDistance surface_distance(const TessSurface& reference, const SurfaceOracle& reference_oracle,
                                 const TessSurface& tessref, const SurfaceOracle& tessref_oracle,
                                 const Parallel& parallel, const std::function<bool(std::uint32_t)>& tessref_patches) {
  SurfaceDistance d;
  std::map<std::uint32_t, double> per_patch;
  d.reference_to_tessref = one_side(reference, tessref_oracle, parallel, per_patch, nullptr);
  d.tessref_to_reference = one_side(tessref, reference_oracle, parallel, per_patch, tessref_patches);
  d.hausdorff = std::max(d.reference_to_tessref.max, d.tessref_to_reference.max);
  std::vector<std::pair<std::uint32_t, double>> patches(per_patch.begin(), per_patch.end());
  const std::size_t n = std::min<std::size_t>(10, patches.size());
  std::partial_sort(patches.begin(), patches.begin() + n, patches.end(),
                    [](const auto& a, const auto& b) { return a.second > b.second || (a.second == b.second && a.first < b.first); });
  d.worst_patches.assign(patches.begin(), patches.begin() + n);
  return d;
}

}  // namespace tessref
