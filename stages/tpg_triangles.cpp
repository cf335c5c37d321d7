// The triangle domain: an outer ring whose three edges follow the outer levels, then concentric
// inner rings following the inner level, spiralling inwards.
#include <algorithm>

#include "stages/tpg_domains.h"
#include "stages/tpg_stitch.h"

namespace tessref::tpg {

using namespace tessref::fixed;

void generate_triangles(const TriangleLevels& lv, bool reverse, bool with_connectivity,
                        DomainOutput& out) {
  Subdivision outer[3];
  for (int e = 0; e < 3; ++e) outer[e] = make_subdivision(lv.outer[e], lv.outer_parity[e]);
  const Subdivision inner = make_subdivision(lv.inner, lv.inner_parity);
  // An inner level of 1 still gets one inner ring, possibly degenerate, to stitch against.
  const int inner_points = std::max(inner.odd() ? 4 : 3, inner.num_points);

  // Outer ring: from the v = 1 corner down the u = 0 edge, then the v = 0 edge, then w = 0; each
  // edge leaves out its last point, which the next edge starts with.
  for (int e = 0; e < 3; ++e) {
    const int last = outer[e].num_points - 1;
    for (int p = 0; p < last; ++p) {
      const Fx16 t = place_point(outer[e], (e & 1) ? p : last - p);
      if (e == 0) out.points.push_back({0, t});
      else if (e == 1) out.points.push_back({t, 0});
      else out.points.push_back({t, kTessOne - t});
    }
  }
  const int first_inner_point = int(out.points.size());

  // Inner rings. A ring's points are the inner subdivision pulled towards the centre: its
  // perpendicular parameter is 2/3 of the subdivision point, and the along-edge parameter
  // shrinks by half of that.
  for (int ring = 1; ring < (inner_points >> 1); ++ring) {
    const int last = inner_points - 1 - ring;
    const Fx16 perp = tess_mul_round(place_point(inner, ring), kTessTwoThirds);
    const Fx16 shift = (perp + 1) / 2;
    for (int e = 0; e < 3; ++e) {
      for (int p = ring; p < last; ++p) {
        const Fx16 t = place_point(inner, (e & 1) ? p : last - (p - ring)) - shift;
        if (e == 0) out.points.push_back({perp, t});
        else if (e == 1) out.points.push_back({t, perp});
        else out.points.push_back({t, kTessOne - t - perp});
      }
    }
  }
  if (!inner.odd()) out.points.push_back({kTessOneThird, kTessOneThird});  // the centre

  if (!with_connectivity) return;
  const TriangleSink emit{&out.indices, reverse};
  int outer_row_points[3] = {outer[0].num_points, outer[1].num_points, outer[2].num_points};
  int inside_base = first_inner_point, outside_base = 0;
  for (int ring = 1; ring < ((inner_points + 1) >> 1); ++ring) {
    const int inside_row_points = inner_points - 2 * ring;
    const int ring_inside_start = inside_base, ring_outside_start = outside_base;
    for (int e = 0; e < 3; ++e) {
      Row in{inside_base}, outr{outside_base};
      if (e == 2) {  // the last side closes the ring on its first points
        in.redirect_k = inside_row_points - 1, in.redirect_to = ring_inside_start;
        outr.redirect_k = outer_row_points[e] - 1, outr.redirect_to = ring_outside_start;
      }
      if (ring == 1) {
        stitch_transition(in, inner.half_points, inner.parity, outr, outer[e].half_points,
                          outer[e].parity, emit);
      } else {
        stitch_regular(true, Diagonals::Mirrored, inside_row_points, in, outr, emit);
      }
      outside_base += outer_row_points[e] - 1;
      inside_base += inside_row_points - 1;
      outer_row_points[e] = inside_row_points;
    }
  }
  if (inner.odd()) emit(outside_base, outside_base + 1, outside_base + 2);  // centre triangle
}

}  // namespace tessref::tpg
