#include "stages/tpg_sweep.h"

#include <bit>
#include <cmath>
#include <limits>

namespace tessref {
namespace {

std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// A float in [lo, hi) from 24 random bits: exact conversions and one rounding, all IEEE.
float uniform(std::uint64_t bits, float lo, float hi) {
  const float unit = float(bits >> 40) / 16777216.0f;
  return lo + (hi - lo) * unit;
}

float level(std::uint64_t& state, SweepRange range) {
  static const float specials[] = {1.0f, 64.0f, 65.0f, 0.0f, -1.5f,
                                   std::numeric_limits<float>::quiet_NaN(),
                                   std::numeric_limits<float>::infinity(), 1.0000001f, 1.00001f,
                                   2.0f, 2.0000002f, 3.0f, 63.0f, 62.5f, 1e30f};
  const std::uint64_t r = splitmix64(state);
  const std::uint64_t kind = r % 10;
  if (kind == 0) {
    const float s = specials[(r >> 8) % std::size(specials)];
    return range == SweepRange::Small && s > 12.0f ? 12.0f : s;
  }
  if (kind <= 2 && range == SweepRange::Full) return float(1 + (r >> 8) % 64);
  return range == SweepRange::Full ? uniform(r, 0.5f, 66.0f) : uniform(r, 0.5f, 12.0f);
}

}  // namespace

std::vector<TessLayout> sweep_layouts() {
  std::vector<TessLayout> out;
  for (TessDomain d : {TessDomain::Triangles, TessDomain::Quads, TessDomain::Isolines})
    for (TessSpacing s :
         {TessSpacing::Equal, TessSpacing::FractionalOdd, TessSpacing::FractionalEven})
      for (TessWinding w : {TessWinding::Ccw, TessWinding::Cw})
        for (bool points : {false, true}) out.push_back(TessLayout{d, s, w, points});
  return out;
}

std::string sweep_name(const TessLayout& l) {
  return std::string(to_string(l.domain)) + "_" + to_string(l.spacing) + "_" +
         to_string(l.winding) + (l.point_mode ? "_points" : "");
}

std::vector<TessLevels> sweep_levels(std::uint64_t seed, std::size_t count, SweepRange range) {
  std::vector<TessLevels> out(count);
  std::uint64_t state = seed;
  for (TessLevels& l : out) {
    for (float& o : l.outer) o = level(state, range);
    for (float& i : l.inner) i = level(state, range);
  }
  return out;
}

std::uint64_t stream_hash(const std::vector<glm::vec3>& stream) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  auto mix = [&h](std::uint32_t word) {
    for (int b = 0; b < 4; ++b) {
      h ^= (word >> (8 * b)) & 0xFFu;
      h *= 0x100000001b3ull;
    }
  };
  mix(std::uint32_t(stream.size()));
  for (const glm::vec3& c : stream)
    for (int k = 0; k < 3; ++k) mix(std::bit_cast<std::uint32_t>(c[k]));
  return h;
}

}  // namespace tessref
