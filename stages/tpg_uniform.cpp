#include "stages/tpg_uniform.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tessref {

const char* to_string(Tessellator t) {
  if (t == Tessellator::RefinementPattern) return "refinement_pattern";
  return t == Tessellator::Uniform ? "uniform" : "primitive_generator";
}

bool parse(const std::string& s, Tessellator& out) {
  for (Tessellator t : {Tessellator::PrimitiveGenerator, Tessellator::Uniform, Tessellator::RefinementPattern})
    if (s == to_string(t)) return out = t, true;
  return false;
}

int uniform_segments(const TessLevels& levels, const TessProfile& profile) {
  float top = 0.0f;
  for (int e = 0; e < 3; ++e) {
    // The TPG's discard rule (GL 4.6, 11.2.2): any relevant outer level <= 0 or NaN.
    if (!(levels.outer[e] > 0.0f)) return 0;
    top = std::max(top, levels.outer[e]);
  }
  // Clamp in float first: ceil of 1e30 or +Inf does not fit an int. Same bounds as the TPG.
  const int max_level = std::clamp(profile.max_level, 2, 64);
  return int(std::ceil(std::min(top, float(max_level))));
}

void generate_uniform(const TessLayout& layout, const TessLevels& levels, const TessProfile& profile,
                      TessDomainPoints& out) {
  if (layout.domain != TessDomain::Triangles)
    throw std::invalid_argument(std::string("uniform tessellation: the ") + to_string(layout.domain) +
                                " domain is not supported (triangles only)");
  out.coords.clear();
  out.indices.clear();
  out.discarded = false;
  out.vertices_per_primitive = layout.point_mode ? 1 : 3;
  const int n = uniform_segments(levels, profile);
  if (n == 0) {
    out.discarded = true;
    return;
  }

  // Each coordinate is its own correctly rounded i / n (not 1 - u - v), so every point lies on
  // the grid, boundary coordinates are exactly 0, and an edge's parameters read the same from
  // both patches that share it.
  const float fn = float(n);
  out.coords.reserve(uniform_point_count(n));
  for (int j = n; j >= 0; --j)
    for (int i = 0; i <= n - j; ++i)
      out.coords.emplace_back(float(i) / fn, float(j) / fn, float(n - i - j) / fn);

  if (layout.point_mode) {
    out.indices.resize(out.coords.size());
    for (std::size_t k = 0; k < out.indices.size(); ++k) out.indices[k] = std::uint32_t(k);
    return;
  }
  // Row j starts after the rows above it: (n - j)(n - j + 1) / 2 points.
  auto at = [n](int i, int j) { return std::uint32_t((n - j) * (n - j + 1) / 2 + i); };
  const bool reverse = layout.winding == TessWinding::Cw;
  auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    out.indices.push_back(a);
    out.indices.push_back(reverse ? c : b);
    out.indices.push_back(reverse ? b : c);
  };
  out.indices.reserve(3 * uniform_triangle_count(n));
  for (int j = n - 1; j >= 0; --j) {
    for (int i = 0; i + j < n; ++i) {
      // Started at the top corner so that n = 1 is the TPG's (0, 1, 2); ccw in (u, v).
      emit(at(i, j + 1), at(i, j), at(i + 1, j));
      if (i + j + 2 <= n) emit(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
    }
  }
}

}  // namespace tessref
