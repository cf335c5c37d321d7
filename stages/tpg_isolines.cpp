// The isoline domain: `density` lines at v = 0, 1/n, ... (never v = 1), each subdivided into
// segments by the detail level with the layout's spacing.
#include "stages/tpg_domains.h"

namespace tessref::tpg {

void generate_isolines(const IsolineLevels& lv, bool with_connectivity, DomainOutput& out) {
  const Subdivision density = make_subdivision(lv.density, lv.density_parity);
  const Subdivision detail = make_subdivision(lv.detail, lv.detail_parity);
  const int lines = density.num_points - 1;  // the line at v = 1 is not drawn
  for (int line = 0; line < lines; ++line) {
    const Fx16 v = place_point(density, line);
    for (int p = 0; p < detail.num_points; ++p) out.points.push_back({place_point(detail, p), v});
  }
  if (!with_connectivity) return;
  for (int line = 0; line < lines; ++line) {
    const std::uint32_t first = std::uint32_t(line * detail.num_points);
    for (int p = 1; p < detail.num_points; ++p) {
      out.indices.push_back(first + p - 1);
      out.indices.push_back(first + p);
    }
  }
}

}  // namespace tessref::tpg
