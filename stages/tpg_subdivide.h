#pragma once
// One-dimensional subdivision of an edge (or an axis of the interior) for a processed level, in
// 16.16 fixed point. This is where llvmpipe's (the D3D11 reference tessellator's) implementation
// choices live: fractional levels blend the subdivisions of floor(level/2) and ceil(level/2) on a
// half edge, and the point that splits when the level grows is picked by a ruler function.
#include "common/fixed_point.h"

namespace tessref::tpg {

using fixed::Fx16;

enum class Parity { Even, Odd };

struct Subdivision {
  Parity parity = Parity::Even;
  int num_points = 0;     // points on the whole edge, both ends included
  int half_points = 0;    // points on one half (the midpoint excluded for even parity)
  int split_point = 0;    // half-edge index past which the floor subdivision lags one point
  Fx16 half_fraction = 0; // fractional part of the (parity-adjusted) half level
  Fx16 inv_segments_floor = 0, inv_segments_ceil = 0;
  bool odd() const { return parity == Parity::Odd; }
};

// level: a clamped, rounded level in 16.16.
Subdivision make_subdivision(Fx16 level, Parity parity);

// Position in [0, 1] (16.16) of point `index` along the edge, 0 <= index < num_points. Symmetric:
// place(num_points - 1 - i) == 1 - place(i) exactly.
Fx16 place_point(const Subdivision& s, int index);

}  // namespace tessref::tpg
