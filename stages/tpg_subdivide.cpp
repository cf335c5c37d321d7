#include "stages/tpg_subdivide.h"

#include <bit>

namespace tessref::tpg {
namespace {

using namespace tessref::fixed;

// 1/n in 16.16, rounded to nearest; n <= 64.
Fx16 reciprocal(int n) { return (kTessOne + Fx16(n) / 2) / Fx16(n); }

// n with its most significant set bit cleared (0 stays 0).
int clear_msb(int n) { return n <= 0 ? 0 : n & ~int(std::bit_floor(unsigned(n))); }

}  // namespace

Subdivision make_subdivision(Fx16 level, Parity parity) {
  Subdivision s;
  s.parity = parity;
  const bool odd = parity == Parity::Odd;

  // Points on the whole edge: odd parity counts ceil(level/2 + 1/2) pairs, even parity ceil(level/2)
  // pairs plus the midpoint.
  const Fx16 half_level = (level + 1) / 2;  // +1: round
  s.num_points = odd ? int((tess_ceil(kTessHalf + half_level) * 2) >> kTessFractionBits)
                     : int((tess_ceil(half_level) * 2) >> kTessFractionBits) + 1;

  // Odd parity centres a segment on the midpoint, so its half level is shifted by 1/2. An even
  // level of exactly 1 (equal spacing, inner level 1) is treated the same way.
  Fx16 half = half_level;
  if (odd || half == kTessHalf) half += kTessHalf;
  const Fx16 half_floor = tess_floor(half), half_ceil = tess_ceil(half);
  s.half_fraction = half - half_floor;
  s.half_points = int(half_ceil >> kTessFractionBits);

  const int floor_units = int(half_floor >> kTessFractionBits);
  if (half_ceil == half_floor) {
    s.split_point = s.half_points + 1;  // nothing to split
  } else if (odd) {
    s.split_point = floor_units == 1 ? 0 : (clear_msb(floor_units - 1) << 1) + 1;
  } else {
    s.split_point = (clear_msb(floor_units) << 1) + 1;
  }

  int floor_segments = int((half_floor * 2) >> kTessFractionBits);
  int ceil_segments = int((half_ceil * 2) >> kTessFractionBits);
  if (odd) {
    floor_segments -= 1;
    ceil_segments -= 1;
  }
  s.inv_segments_floor = reciprocal(floor_segments);
  s.inv_segments_ceil = reciprocal(ceil_segments);
  return s;
}

Fx16 place_point(const Subdivision& s, int index) {
  // Work on the first half and mirror: this makes every edge symmetric bit for bit.
  bool mirrored = false;
  if (index >= s.half_points) {
    index = 2 * s.half_points - index - (s.odd() ? 1 : 0);
    mirrored = true;
  }
  if (index == s.half_points) return kTessHalf;  // the midpoint, exact

  const Fx16 on_ceil = Fx16(index) * s.inv_segments_ceil;
  const Fx16 on_floor = Fx16(index > s.split_point ? index - 1 : index) * s.inv_segments_floor;
  // Both are <= 1/2, so the blend fits in 32 bits before the shift back to 16.16.
  Fx16 location = on_floor * (kTessOne - s.half_fraction) + on_ceil * s.half_fraction;
  location = (location + kTessHalf) >> kTessFractionBits;
  return mirrored ? kTessOne - location : location;
}

}  // namespace tessref::tpg
