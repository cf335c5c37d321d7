// The quad domain: an outer ring (u = 0, v = 0, u = 1, v = 1 edges), then inner rings following
// the two inner levels; where one inner level runs out first the centre is a strip of quads (odd)
// or a degenerate ring that is a single row of points (even).
#include <algorithm>

#include "stages/tpg_domains.h"
#include "stages/tpg_stitch.h"

namespace tessref::tpg {

using namespace tessref::fixed;

void generate_quads(const QuadLevels& lv, bool reverse, bool with_connectivity,
                    DomainOutput& out) {
  Subdivision outer[4], inner[2];
  for (int e = 0; e < 4; ++e) outer[e] = make_subdivision(lv.outer[e], lv.outer_parity[e]);
  int inner_points[2];
  for (int a = 0; a < 2; ++a) {
    inner[a] = make_subdivision(lv.inner[a], lv.inner_parity[a]);
    inner_points[a] = std::max(inner[a].odd() ? 4 : 3, inner[a].num_points);
  }
  constexpr int U = 0, V = 1;

  // Outer ring, from (0, 1) down the u = 0 edge, along v = 0, up u = 1, back along v = 1.
  for (int e = 0; e < 4; ++e) {
    const int last = outer[e].num_points - 1;
    for (int p = 0; p < last; ++p) {
      const Fx16 t = place_point(outer[e], (e == 1 || e == 2) ? p : last - p);
      if (e & 1) out.points.push_back({t, e == 3 ? kTessOne : 0});
      else out.points.push_back({e == 2 ? kTessOne : 0, t});
    }
  }
  const int first_inner_point = int(out.points.size());

  // Inner rings; edge e runs along axis (e + 1) & 1 at a fixed value of the other axis.
  const int point_rings = std::min(inner_points[U], inner_points[V]) >> 1;
  for (int ring = 1; ring < point_rings; ++ring) {
    const int last[2] = {inner_points[U] - 1 - ring, inner_points[V] - 1 - ring};
    for (int e = 0; e < 4; ++e) {
      const int perp_axis = e & 1, along_axis = (e + 1) & 1;
      const Fx16 perp = place_point(inner[perp_axis], e < 2 ? ring : last[perp_axis]);
      for (int p = ring; p < last[along_axis]; ++p) {
        const int q = (e == 1 || e == 2) ? p : last[along_axis] - (p - ring);
        const Fx16 t = place_point(inner[along_axis], q);
        if (along_axis == V) out.points.push_back({perp, t});
        else out.points.push_back({t, perp});
      }
    }
  }
  // Even parity on the shorter axis leaves a degenerate ring: one row of points on the centre line.
  if (inner_points[U] > inner_points[V] && !inner[V].odd()) {
    for (int p = point_rings; p <= inner_points[U] - 1 - point_rings; ++p)
      out.points.push_back({place_point(inner[U], p), kTessHalf});
  } else if (inner_points[V] >= inner_points[U] && !inner[U].odd()) {
    for (int p = inner_points[V] - 1 - point_rings; p >= point_rings; --p)
      out.points.push_back({kTessHalf, place_point(inner[V], p)});
  }

  if (!with_connectivity) return;
  const TriangleSink emit{&out.indices, reverse};
  const int rows_to_centre[2] = {(inner_points[U] + 1) >> 1, (inner_points[V] + 1) >> 1};
  const int rings = std::min(rows_to_centre[U], rows_to_centre[V]);
  // The ring (if any) that is the degenerate row, per axis the ring's side runs along.
  const int degenerate_ring[2] = {!inner[V].odd() ? rows_to_centre[V] - 1 : -1,
                                  !inner[U].odd() ? rows_to_centre[U] - 1 : -1};
  int outer_row_points[4];
  int outer_half_points[4];
  Parity outer_parity[4];
  for (int e = 0; e < 4; ++e) {
    outer_row_points[e] = outer[e].num_points;
    outer_half_points[e] = outer[e].half_points;
    outer_parity[e] = outer[e].parity;
  }
  int inside_base = first_inner_point, outside_base = 0;
  for (int ring = 1; ring < rings; ++ring) {
    const int inside_row_points[2] = {inner_points[U] - 2 * ring, inner_points[V] - 2 * ring};
    const int ring_inside_start = inside_base, ring_outside_start = outside_base;
    for (int e = 0; e < 4; ++e) {
      const int axis = (e + 1) & 1;
      const bool degenerate = ring == degenerate_ring[axis];
      Row in{inside_base}, outr{outside_base};
      if (e == 3) {  // the last side closes the ring on its first points
        outr.redirect_k = outer_row_points[e] - 1, outr.redirect_to = ring_outside_start;
        if (degenerate) {
          // The degenerate row is walked backwards on the way back.
          const int b = inside_base + 1;
          in = Row{(2 * b - 1) - b, -1};
        } else {
          in.redirect_k = inside_row_points[axis] - 1, in.redirect_to = ring_inside_start;
        }
      } else if (e == 2 && degenerate) {
        in = Row{inside_base, -1};
      }
      if (ring == 1) {
        stitch_transition(in, inner[axis].half_points, inner[axis].parity, outr,
                          outer_half_points[e], outer_parity[e], emit);
      } else {
        stitch_regular(true, Diagonals::Mirrored, inside_row_points[axis], in, outr, emit);
      }
      outside_base += outer_row_points[e] - 1;
      inside_base += (e == 2 && degenerate ? -1 : 1) * (inside_row_points[axis] - 1);
      outer_row_points[e] = inside_row_points[axis];
    }
    if (ring == 1) {
      for (int e = 0; e < 4; ++e) {
        outer_half_points[e] = inner[e & 1].half_points;
        outer_parity[e] = inner[e & 1].parity;
      }
    }
  }

  // The centre strip of quads, where the shorter inner axis is odd.
  auto strip_quads = [&](int long_axis) {
    const int short_axis = 1 - long_axis;
    return (((inner_points[long_axis] >> 1) - (inner_points[short_axis] >> 1)) << 1) +
           (inner[long_axis].odd() ? 1 : 2);
  };
  if (inner_points[U] > inner_points[V] && inner[V].odd()) {
    const int quads = strip_quads(U);
    const int b = outside_base + quads + 2;
    // Inside row: walked backwards from the far end; its first position is the ring's first point.
    const Row in{(2 * b + quads) - b, -1, 0, outside_base};
    const Row outr{outside_base + 1};
    stitch_regular(false, Diagonals::InsideToOutside, quads + 1, in, outr, emit);
  } else if (inner_points[V] >= inner_points[U] && inner[U].odd()) {
    const int quads = strip_quads(V);
    const int b = outside_base + quads + 1;
    const Row in{(2 * b + quads) - b, -1};
    const Row outr{outside_base};
    const Diagonals d = inner[V].odd() ? Diagonals::InsideToOutsideExceptMiddle
                                       : Diagonals::InsideToOutside;
    stitch_regular(false, d, quads + 1, in, outr, emit);
  }
}

}  // namespace tessref::tpg
