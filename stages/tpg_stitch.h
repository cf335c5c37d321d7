#pragma once
// Connectivity between two rows of domain points: an outer row and the next row inwards. The
// triangle order and the diagonal choices are llvmpipe's (not fixed by the GL spec).
#include <cstdint>
#include <vector>

#include "stages/tpg_subdivide.h"

namespace tessref::tpg {

// A row of points along one side of a ring, addressed by position k along the row. Rows run
// forwards or backwards through the point array, and one position may be redirected (the last
// point of a ring's last side is the ring's first point).
struct Row {
  int origin = 0;
  int step = 1;
  int redirect_k = -1;
  int redirect_to = 0;
  std::uint32_t operator()(int k) const {
    return std::uint32_t(k == redirect_k ? redirect_to : origin + step * k);
  }
};

// Collects triangles given in the generator's reference orientation, and stores them in the
// orientation the TES asked for.
struct TriangleSink {
  std::vector<std::uint32_t>* indices;
  bool reverse;  // layout(cw)
  void operator()(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
    indices->push_back(a);
    indices->push_back(reverse ? c : b);
    indices->push_back(reverse ? b : c);
  }
};

enum class Diagonals { InsideToOutside, InsideToOutsideExceptMiddle, Mirrored };

// Two rows of equal subdivision (inside has one point fewer at each end when `trapezoid`).
void stitch_regular(bool trapezoid, Diagonals diagonals, int inside_points, const Row& inside,
                    const Row& outside, const TriangleSink& emit);

// The outermost transition ring: rows of unrelated levels, stitched half by half in the order of
// a ruler function so that a row's triangles change gradually as its level grows.
void stitch_transition(const Row& inside, int inside_half_points, Parity inside_parity,
                       const Row& outside, int outside_half_points, Parity outside_parity,
                       const TriangleSink& emit);

}  // namespace tessref::tpg
