#pragma once
// Level-set sweeps for comparing primitive generators (tessref, llvmpipe, a GPU driver): the
// layouts, a portable deterministic level generator and a hash of each emitted stream. The same
// sweep is produced on every machine and compiler, so a dataset captured on one driver can be
// checked anywhere.
#include <cstdint>
#include <string>
#include <vector>

#include "stages/tpg.h"

namespace tessref {

// Every domain x spacing x winding x point mode: 36 layouts.
std::vector<TessLayout> sweep_layouts();
// "triangles_fractional_odd_ccw" (+ "_points" in point mode).
std::string sweep_name(const TessLayout& layout);

enum class SweepRange {
  Full,   // non-integer levels over (0.5, 66), integers 1..64, and the boundary values
          // (1, 64, 65, 0, negative, NaN, +Inf, just above 1 and 2)
  Small,  // non-integer levels in (0.5, 12) and the boundary values: short streams
};
// Level sets from splitmix64(seed): only integer arithmetic and exact float conversions, so the
// values are the same on every platform.
std::vector<TessLevels> sweep_levels(std::uint64_t seed, std::size_t count, SweepRange range);

// FNV-1a (64-bit) over the vertex count and the IEEE-754 bits of every component (x, y, z).
std::uint64_t stream_hash(const std::vector<glm::vec3>& stream);

}  // namespace tessref
