// Fuzzes the primitive generator (stages/tpg.h): any domain, spacing, winding and point mode, any
// level bits (NaN, infinities, negative, huge, denormal, just above an integer), any profile.
//
// generate_tessellation never throws. A finding: a crash, UB, or a broken invariant:
//   - gl_TessCoord components in [0, 1]; triangles: u + v + w = 1 (exact: multiples of 2^-16);
//     quads and isolines: z = 0; isolines: v < 1 (no line at v = 1);
//   - indices in range, one per point in point mode; no triangle repeats a point; every point
//     belongs to a primitive; all triangles turn the same way (or are flat, or are slivers of
//     fractional spacing that llvmpipe turns the same way), opposite for cw;
//   - no output for a discarded patch; discarded exactly when the spec says (outer level <= 0 or
//     NaN); the point count bounded by what the clamped levels allow;
//   - the same result into a reused TessDomainPoints as into a fresh one.
#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "stages/tpg.h"

namespace {

using namespace tessref;

char g_case[512];  // the input's layout, profile and levels, for the message

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "fuzz_tpg: invariant broken: %s\n  %s\n", what, g_case);
    std::abort();
  }
}

// A level: raw bits half of the time, else a value near the interesting range (k/256 for
// k in [-512, 17920): up to 70) or one of the special values.
float level(FuzzedDataProvider& in) {
  switch (in.ConsumeIntegralInRange(0, 3)) {
    case 0: return std::bit_cast<float>(in.ConsumeIntegral<std::uint32_t>());
    case 1: return float(in.ConsumeIntegralInRange(-512, 17919)) / 256.0f;
    case 2: return float(in.ConsumeIntegralInRange(0, 66));
    default: {
      static const float kSpecial[] = {NAN, -NAN, INFINITY, -INFINITY, 0.0f, -0.0f, 1e-45f, 1.0f + 0x1p-17f,
                                       1.0f + 0x1p-16f, 3.0f - 0x1p-22f, 63.0f + 0x1p-17f, 64.0f, 65.0f, 1e38f};
      return kSpecial[in.ConsumeIntegralInRange<std::size_t>(0, std::size(kSpecial) - 1)];
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  TessLayout layout;
  layout.domain = static_cast<TessDomain>(in.ConsumeIntegralInRange(0, 2));
  layout.spacing = static_cast<TessSpacing>(in.ConsumeIntegralInRange(0, 2));
  layout.winding = static_cast<TessWinding>(in.ConsumeIntegralInRange(0, 1));
  layout.point_mode = in.ConsumeBool();
  TessProfile profile = in.ConsumeBool() ? TessProfile::llvmpipe() : TessProfile::spec_literal();
  if (in.ConsumeBool()) profile.max_level = in.ConsumeIntegral<int>();  // clamped to 2..64
  TessLevels levels;
  for (float& l : levels.outer) l = level(in);
  for (float& l : levels.inner) l = level(in);

  std::snprintf(g_case, sizeof g_case,
                "%s %s %s%s, profile %s max_level %d, outer %a %a %a %a (%g %g %g %g), inner %a %a (%g %g)",
                to_string(layout.domain), to_string(layout.spacing), to_string(layout.winding),
                layout.point_mode ? " point_mode" : "", profile.name.c_str(), profile.max_level,
                double(levels.outer[0]), double(levels.outer[1]), double(levels.outer[2]), double(levels.outer[3]),
                double(levels.outer[0]), double(levels.outer[1]), double(levels.outer[2]), double(levels.outer[3]),
                double(levels.inner[0]), double(levels.inner[1]), double(levels.inner[0]), double(levels.inner[1]));
  const TessDomainPoints out = generate_tessellation(layout, levels, profile);
  TessDomainPoints reused;
  reused.coords.assign(7, glm::vec3(2.0f));
  reused.indices.assign(5, 99);
  reused.discarded = true;
  generate_tessellation(layout, levels, profile, reused);
  check(reused.coords == out.coords && reused.indices == out.indices && reused.discarded == out.discarded &&
            reused.vertices_per_primitive == out.vertices_per_primitive,
        "a reused output equals a fresh one");

  const int outer_count = layout.domain == TessDomain::Triangles ? 3 : layout.domain == TessDomain::Quads ? 4 : 2;
  bool discard = false;
  for (int e = 0; e < outer_count; ++e) discard |= !(levels.outer[e] > 0.0f);
  check(out.discarded == discard, "discarded exactly for an outer level <= 0 or NaN");
  if (out.discarded) {
    check(out.coords.empty() && out.indices.empty(), "a discarded patch has no output");
    return 0;
  }
  const int per = out.vertices_per_primitive;
  check(per == (layout.point_mode ? 1 : layout.domain == TessDomain::Isolines ? 2 : 3), "vertices per primitive");
  check(!out.coords.empty() && out.indices.size() % per == 0, "whole primitives");

  // Every relevant level clamps to at most max_level (and rounds up to at most one more), so no
  // edge has more than max_level + 1 segments and no domain more than (max + 2)^2 points.
  const int max_level = std::clamp(profile.max_level, 2, 64);
  const std::size_t side = std::size_t(max_level) + 2;
  check(out.coords.size() <= side * side, "point count within what clamped levels allow");

  for (const glm::vec3& c : out.coords) {
    check(c.x >= 0.0f && c.x <= 1.0f && c.y >= 0.0f && c.y <= 1.0f && c.z >= 0.0f && c.z <= 1.0f,
          "gl_TessCoord in [0, 1]");
    if (layout.domain == TessDomain::Triangles) check(c.x + c.y + c.z == 1.0f, "u + v + w = 1");
    else check(c.z == 0.0f, "z = 0 outside triangles");
    if (layout.domain == TessDomain::Isolines) check(c.y < 1.0f, "no isoline at v = 1");
  }

  std::vector<bool> used(out.coords.size(), false);
  for (std::uint32_t i : out.indices) {
    check(i < out.coords.size(), "indices in range");
    used[i] = true;
  }
  check(std::all_of(used.begin(), used.end(), [](bool u) { return u; }), "every point in a primitive");
  if (layout.point_mode) {
    check(out.indices.size() == out.coords.size(), "one point per domain point");
    return 0;
  }
  int turn = 0;  // the sign of the first non-flat triangle's area
  for (std::size_t t = 0; per == 3 && t < out.indices.size(); t += 3) {
    const std::uint32_t a = out.indices[t], b = out.indices[t + 1], c = out.indices[t + 2];
    check(a != b && b != c && a != c, "no triangle repeats a point");
    const glm::vec3 p = out.coords[a], q = out.coords[b], r = out.coords[c];
    // Exact in double: coordinates are multiples of 2^-16 in [0, 1].
    const double area = (double(q.x) - p.x) * (double(r.y) - p.y) - (double(q.y) - p.y) * (double(r.x) - p.x);
    const int sign = (area > 0) - (area < 0);
    if (sign != 0 && turn == 0) turn = sign;
    // Fractional levels just above a ring's minimum (inner 2.00002, fractional_even) give a ring
    // thinner than the 16.16 grid, next to which a sliver can turn the other way: llvmpipe's
    // stream is the same, bit for bit (docs/fuzzing.md), so only those are let through.
    const bool sliver = layout.spacing != TessSpacing::Equal && std::fabs(area) < 0x1p-14;
    check(sign == 0 || sign == turn || sliver, "all triangles turn the same way");
  }
  for (std::size_t s = 0; per == 2 && s < out.indices.size(); s += 2)
    check(out.indices[s] != out.indices[s + 1], "no isoline segment repeats a point");
  // The winding flips every triangle.
  if (per == 3 && turn != 0) {
    TessLayout flipped = layout;
    flipped.winding = layout.winding == TessWinding::Ccw ? TessWinding::Cw : TessWinding::Ccw;
    const TessDomainPoints other = generate_tessellation(flipped, levels, profile);
    check(other.coords == out.coords && other.indices.size() == out.indices.size(), "winding keeps the points");
    for (std::size_t t = 0; t < out.indices.size(); t += 3)
      check(other.indices[t] == out.indices[t] && other.indices[t + 1] == out.indices[t + 2] &&
                other.indices[t + 2] == out.indices[t + 1],
            "cw swaps the last two vertices of each triangle");
  }
  return 0;
}
