#pragma once
// The refinement pattern of seed 001 (Boubekeur & Schlick, "Generic Mesh Refinement on GPU",
// Sections 3.2-3.3): one uniformly tessellated triangle per level of detail, RP_0 .. RP_6, drawn
// once per coarse triangle; each pattern vertex carries its barycentric coordinates (the paper's
// V_xyz = {w, u, v}) and the evaluation program places it on the patch. docs/uniform-subdivision.md
// (section "The refinement pattern") compares it with the primitive generator and the uniform grid.
//
// Level of detail: RP_k is the barycentric grid of 2^k segments per edge, the triangle after k
// recursive 4-splits (the paper's "RP at 64x64 ... a recursive subdivision at level 6"). A patch's
// levels pick k = ceil(log2(largest outer level)), clamped to [0, 6] and to the profile's largest
// level: level 1 gives RP_0 (the coarse triangle), 2 gives RP_1, 3 and 4 give RP_2, 33 to 64 RP_6.
// Inner levels and the spacing are not used; a patch the GL generator discards (an outer level
// <= 0 or NaN) is discarded.
//
// Two properties follow from the powers of two, and the tests hold them:
// - every coordinate is a dyadic fraction i / 2^k, exact in float: w = 1 - u - v exactly, and the
//   points of a shared edge have the same bits from both patches;
// - the patterns are nested: RP_(k-1)'s points are RP_k's first points, in the same order, so one
//   vertex buffer (RP_6's) serves every level of detail, each level only an index list.
#include <cstddef>

#include "stages/tpg.h"

namespace tessref {

inline constexpr int kMaxRefinementLod = 6;  // 64 segments per edge, GL's smallest MAX_TESS_GEN_LEVEL

// k for the patch's levels, or -1 when the patch is discarded.
int refinement_lod(const TessLevels& levels, const TessProfile& profile);
inline int refinement_segments(int lod) { return 1 << lod; }

// Fills out with RP_k for a triangle layout (throws std::invalid_argument for quads and
// isolines). Points: the corners in the order the GL generator gives its single triangle
// ((0,1,0), (0,0,1), (1,0,0)), then the points each further 4-split adds, level by level, each
// level's row by row from v = 1 down to v = 0, u increasing within a row. Triangles: the grid's,
// row by row, counter-clockwise in (u, v) like the generator's, reversed for layout(cw). Point
// mode: every point once, no triangles.
void generate_refinement_pattern(const TessLayout& layout, const TessLevels& levels,
                                 const TessProfile& profile, TessDomainPoints& out);

// What RP_k holds: (2^k + 1)(2^k + 2) / 2 points and 4^k triangles.
inline std::size_t refinement_point_count(int lod) {
  const std::size_t n = std::size_t(1) << lod;
  return (n + 1) * (n + 2) / 2;
}
inline std::size_t refinement_triangle_count(int lod) { return std::size_t(1) << (2 * lod); }

}  // namespace tessref
