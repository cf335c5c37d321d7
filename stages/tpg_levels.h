#pragma once
// The levels as the primitive generator uses them (GL 4.6 section 11.2.2): after the discard test,
// clamping and rounding per the spacing, with the segment count each gives. Computed by the same
// rules generate_tessellation applies (stages/tpg.cpp), for tools that show them (tessref inspect).
// Kept out of tpg.h so that adding it rebuilt nothing that includes the generator.
#include <array>

#include "stages/tpg.h"

namespace tessref {

struct ProcessedTessLevels {
  bool discarded = false;        // a relevant outer level <= 0 or NaN: nothing below is set
  int outer_count = 0;           // relevant outer levels: 3 triangles, 4 quads, 2 isolines
  int inner_count = 0;           // relevant inner levels: 1 triangles, 2 quads, 0 isolines
  std::array<float, 4> outer{};  // clamped (equal spacing: also rounded up); isolines: [0] lines
  std::array<float, 2> inner{};  // clamped, after the 1 + epsilon rule (11.2.2.1)
  // Segments each level gives (points on the edge or axis - 1): the level rounded up to the
  // next integer (equal), odd integer (fractional_odd) or even integer (fractional_even).
  std::array<int, 4> outer_segments{};
  std::array<int, 2> inner_segments{};
};

ProcessedTessLevels process_tess_levels(const TessLayout& layout, const TessLevels& levels,
                                        const TessProfile& profile = TessProfile::llvmpipe());

}  // namespace tessref
