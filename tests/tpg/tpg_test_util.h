#pragma once
// Helpers shared by the TPG tests: random level sets with the boundary values mixed in, the
// segment counts the GL spec fixes for a level, and what the pattern tests measure.
#include <cmath>
#include <limits>
#include <random>

#include <glm/glm.hpp>

#include "stages/tpg.h"

namespace tessref::test {

// A random level: mostly non-integer values across (and past) the valid range, with the values
// the spec singles out (1, 64, 65, 0, negative, NaN, +Inf) and values just above 1 and 2.
inline float random_level(std::mt19937& rng) {
  static const float specials[] = {1.0f, 64.0f, 65.0f, 0.0f, -1.5f,
                                   std::numeric_limits<float>::quiet_NaN(),
                                   std::numeric_limits<float>::infinity(), 1.0000001f, 1.00001f,
                                   2.0f, 2.0000002f, 3.0f, 63.0f, 62.5f, 1e30f};
  std::uniform_int_distribution<int> pick(0, 9);
  if (pick(rng) == 0)
    return specials[std::uniform_int_distribution<int>(0, std::size(specials) - 1)(rng)];
  if (pick(rng) < 3) return float(std::uniform_int_distribution<int>(1, 64)(rng));
  return std::uniform_real_distribution<float>(0.5f, 66.0f)(rng);
}

inline TessLevels random_levels(std::mt19937& rng) {
  TessLevels l;
  for (float& o : l.outer) o = random_level(rng);
  for (float& i : l.inner) i = random_level(rng);
  return l;
}

// The number of segments the spec gives an outer edge (11.2.2), llvmpipe profile: fractional
// levels are first rounded to 16.16 (so odd levels in (1, 1 + 2^-17] count as 1).
inline int expected_segments(float level, TessSpacing spacing, bool literal_odd = false) {
  auto to_fixed = [](float x) { return std::nearbyint(double(x) * 65536.0) / 65536.0; };
  switch (spacing) {
    case TessSpacing::Equal:
      return int(std::ceil(std::fmin(64.0f, std::fmax(1.0f, level))));
    case TessSpacing::FractionalEven: {
      const double c = to_fixed(std::fmin(64.0f, std::fmax(2.0f, level)));
      const int n = int(std::ceil(c));
      return n + (n & 1);
    }
    case TessSpacing::FractionalOdd: {
      const float clamped = std::fmin(63.0f, std::fmax(1.0f, level));
      double c = to_fixed(clamped);
      if (literal_odd && clamped > 1.0f && c == 1.0) c = 1.0 + 1.0 / 65536;
      const int n = int(std::ceil(c));
      return n + 1 - (n & 1);
    }
  }
  return 0;
}

// Triangles, fractional_odd, counter-clockwise: the layout the pattern tests draw with.
inline const TessLayout kCcwTriangles{TessDomain::Triangles, TessSpacing::FractionalOdd, TessWinding::Ccw, false};

// Every outer level `outer`, every inner level `inner`.
inline TessLevels levels_of(float outer, float inner = 1.0f) {
  TessLevels l;
  l.outer = {outer, outer, outer, outer};
  l.inner = {inner, inner};
  return l;
}

// Twice the signed area in (u, v) of pattern triangle t: positive for counter-clockwise.
inline double area2(const TessDomainPoints& p, std::size_t t) {
  const glm::dvec3 a = p.coords[p.indices[3 * t]], b = p.coords[p.indices[3 * t + 1]],
                   c = p.coords[p.indices[3 * t + 2]];
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

}  // namespace tessref::test
