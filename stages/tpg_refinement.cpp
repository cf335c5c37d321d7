#include "stages/tpg_refinement.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace tessref {

int refinement_lod(const TessLevels& levels, const TessProfile& profile) {
  float top = 0.0f;
  for (int e = 0; e < 3; ++e) {
    // The generator's discard rule (GL 4.6, 11.2.2): any relevant outer level <= 0 or NaN.
    if (!(levels.outer[e] > 0.0f)) return -1;
    top = std::max(top, levels.outer[e]);
  }
  const int max_level = std::clamp(profile.max_level, 2, 64);
  int k = 0;
  // Compared in float: 2^k is exact, and +Inf simply stops at the largest level.
  while (k < kMaxRefinementLod && float(1 << k) < top && (2 << k) <= max_level) ++k;
  return k;
}

void generate_refinement_pattern(const TessLayout& layout, const TessLevels& levels,
                                 const TessProfile& profile, TessDomainPoints& out) {
  if (layout.domain != TessDomain::Triangles)
    throw std::invalid_argument(std::string("refinement pattern: the ") + to_string(layout.domain) +
                                " domain is not supported (triangles only)");
  out.coords.clear();
  out.indices.clear();
  out.discarded = false;
  out.vertices_per_primitive = layout.point_mode ? 1 : 3;
  const int lod = refinement_lod(levels, profile);
  if (lod < 0) {
    out.discarded = true;
    return;
  }
  const int n = refinement_segments(lod);

  // The split that first makes grid point (i, j): the smallest s with both on the 2^s grid.
  auto level_of = [n](int i, int j) {
    int s = 0;
    for (int step = n; i % step != 0 || j % step != 0; step /= 2) ++s;
    return s;
  };
  // Row-major slot of (i, j), rows from j = n down, then the point index of each slot.
  auto slot = [n](int i, int j) { return std::size_t((n - j) * (n - j + 1) / 2 + i); };
  std::vector<std::uint32_t> index(refinement_point_count(lod));
  out.coords.reserve(index.size());
  const float fn = float(n);  // i / n is exact: n is a power of two
  for (int s = 0; s <= lod; ++s)
    for (int j = n; j >= 0; --j)
      for (int i = 0; i <= n - j; ++i)
        if (level_of(i, j) == s) {
          index[slot(i, j)] = std::uint32_t(out.coords.size());
          out.coords.emplace_back(float(i) / fn, float(j) / fn, float(n - i - j) / fn);
        }

  if (layout.point_mode) {
    out.indices.resize(out.coords.size());
    for (std::size_t k = 0; k < out.indices.size(); ++k) out.indices[k] = std::uint32_t(k);
    return;
  }
  auto at = [&](int i, int j) { return index[slot(i, j)]; };
  const bool reverse = layout.winding == TessWinding::Cw;
  auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    out.indices.push_back(a);
    out.indices.push_back(reverse ? c : b);
    out.indices.push_back(reverse ? b : c);
  };
  out.indices.reserve(3 * refinement_triangle_count(lod));
  for (int j = n - 1; j >= 0; --j)
    for (int i = 0; i + j < n; ++i) {
      emit(at(i, j + 1), at(i, j), at(i + 1, j));  // ccw in (u, v), as the generator's
      if (i + j + 2 <= n) emit(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
    }
}

}  // namespace tessref
