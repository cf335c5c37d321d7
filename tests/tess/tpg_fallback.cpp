// Until stages/tpg.cpp lands, a tiny stand-in generator lets the executor tests run (uniform grid,
// integer levels). Tests that need the real generator's invariance call real_tpg() and skip.
#include "tess_test_util.h"

#if __has_include("../../stages/tpg.cpp")
bool real_tpg() { return true; }
#else
#include <cmath>

bool real_tpg() { return false; }

namespace tessref {

void generate_tessellation(const TessLayout& layout, const TessLevels& levels,
                           const TessProfile& profile, TessDomainPoints& out) {
  out = TessDomainPoints{};
  const int edges = layout.domain == TessDomain::Triangles ? 3 : layout.domain == TessDomain::Quads ? 4 : 2;
  for (int e = 0; e < edges; ++e)
    if (!(levels.outer[e] > 0.0f)) {
      out.discarded = true;
      return;
    }
  const int n = int(std::min(64.0f, std::max(1.0f, std::ceil(levels.outer[0]))));
  out.vertices_per_primitive = layout.point_mode ? 1 : layout.domain == TessDomain::Isolines ? 2 : 3;
  auto tri = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    out.indices.insert(out.indices.end(), {a, b, c});
  };
  if (layout.domain == TessDomain::Triangles) {
    std::vector<std::vector<std::uint32_t>> id(n + 1);
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i + j <= n; ++i) {
        const float u = float(i) / float(n), v = float(j) / float(n);
        id[j].push_back(std::uint32_t(out.coords.size()));
        out.coords.emplace_back(u, v, (1.0f - u) - v);
      }
    if (!layout.point_mode)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i + j < n; ++i) {
          tri(id[j][i], id[j][i + 1], id[j + 1][i]);
          if (i + j + 1 < n) tri(id[j][i + 1], id[j + 1][i + 1], id[j + 1][i]);
        }
  } else {
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) out.coords.emplace_back(float(i) / n, float(j) / n, 0.0f);
    if (!layout.point_mode && layout.domain == TessDomain::Quads)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const std::uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
          tri(a, b, c);
          tri(b, d, c);
        }
  }
  if (layout.point_mode)
    for (std::uint32_t i = 0; i < out.coords.size(); ++i) out.indices.push_back(i);
}

}  // namespace tessref
#endif
