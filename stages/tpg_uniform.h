#pragma once
// Uniform subdivision: the alternative to the primitive generator that Vlachos et al. used for
// PN triangles on the CPU (seed 000). A triangle patch becomes n^2 sub-triangles on the
// barycentric grid (i/n, j/n, k/n), i + j + k = n; the TES then evaluates the patch there exactly
// as it does at the generator's points. docs/uniform-subdivision.md compares the two.
#include <cstdint>

#include "stages/tpg.h"

namespace tessref {

// Which pattern a patch gets from its levels.
// RefinementPattern: seed 001's refinement patterns RP_k (stages/tpg_refinement.h).
enum class Tessellator : std::uint8_t { PrimitiveGenerator, Uniform, RefinementPattern };

// "primitive_generator" | "uniform" | "refinement_pattern"
const char* to_string(Tessellator t);
bool parse(const std::string& s, Tessellator& out);

// The number of segments per edge: the largest of the three outer levels rounded up, clamped
// to [1, profile.max_level]; 0 when the TPG would discard the patch (an outer level <= 0 or NaN).
// The inner level and the spacing are not used: one n keeps every edge of a patch alike, and a
// mesh drawn with constant levels stays watertight (adaptive levels would give T-junctions).
int uniform_segments(const TessLevels& levels, const TessProfile& profile);

// Fills out with the uniform pattern for a triangle layout (throws std::invalid_argument for
// quads and isolines). Points go row by row from v = 1 down to v = 0, u increasing within a row,
// so n = 1 gives the TPG's single triangle point for point and index for index; triangles are
// counter-clockwise in (u, v) like the TPG's, reversed for layout(cw). Point mode: every point
// once, no triangles.
void generate_uniform(const TessLayout& layout, const TessLevels& levels, const TessProfile& profile,
                      TessDomainPoints& out);

// (n + 1)(n + 2) / 2 points and n^2 triangles: what generate_uniform makes for n segments.
inline std::size_t uniform_point_count(int n) { return std::size_t(n + 1) * std::size_t(n + 2) / 2; }
inline std::size_t uniform_triangle_count(int n) { return std::size_t(n) * std::size_t(n); }

}  // namespace tessref
