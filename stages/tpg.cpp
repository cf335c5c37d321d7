// The primitive generator's front: level validation, clamping and rounding (fixed by the GL
// spec, section 11.2.2), then the domain generators (implementation choices, llvmpipe's).
#include "stages/tpg.h"

#include <algorithm>
#include <cmath>

#include "stages/tpg_domains.h"
#include "stages/tpg_levels.h"
#include "stages/tpg_stitch.h"

namespace tessref {
namespace {

using namespace tessref::fixed;
using tpg::Parity;

// "If any of the relevant outer tessellation levels is less than or equal to zero or is a
// floating-point NaN, the patch is discarded." (11.2.2)
bool discards(float level) { return !(level > 0.0f); }

struct Range {
  float lo, hi;
};

// "equal_spacing: clamped to the range [1, max]; fractional_even_spacing: [2, max];
// fractional_odd_spacing: [1, max - 1]" (11.2.2), where max is even; kept odd/even otherwise.
Range clamp_range(TessSpacing spacing, int max_level) {
  const int max_even = max_level & ~1, max_odd = (max_level & 1) ? max_level : max_level - 1;
  switch (spacing) {
    case TessSpacing::Equal: return {1.0f, float(max_level)};
    case TessSpacing::FractionalEven: return {2.0f, float(max_even)};
    case TessSpacing::FractionalOdd: return {1.0f, float(max_odd)};
  }
  return {1.0f, float(max_level)};
}

// fmin/fmax, not comparisons: a NaN inner level clamps to the lower bound.
float clamp_level(float level, Range r) { return std::fmin(r.hi, std::fmax(r.lo, level)); }

Parity parity_of_integer(float level) {
  return (static_cast<int>(level) & 1) ? Parity::Odd : Parity::Even;
}

// Per-level processing shared by every domain.
struct LevelRules {
  TessSpacing spacing;
  Range range;
  const TessProfile* profile;

  float clamp_outer(float level) const {
    const float c = clamp_level(level, range);
    // "equal_spacing: ... rounded up to the nearest integer" (11.2.2)
    return spacing == TessSpacing::Equal ? std::ceil(c) : c;
  }
  Parity parity(float clamped) const {
    switch (spacing) {
      case TessSpacing::Equal: return parity_of_integer(clamped);
      case TessSpacing::FractionalOdd: return Parity::Odd;
      case TessSpacing::FractionalEven: return Parity::Even;
    }
    return Parity::Even;
  }
  Fx16 to_fixed(float clamped) const {
    Fx16 f = tess_from_float(clamped);
    // llvmpipe: a fractional_odd level in (1, 1 + 2^-17] rounds to exactly 1 in 16.16. The
    // literal spec reading keeps any level above 1 above 1.
    if (!profile->odd_level_collapses_near_one && spacing == TessSpacing::FractionalOdd &&
        clamped > 1.0f && f == kTessOne)
      f = kTessOne + 1;
    return f;
  }
  // The inner level's lower bound: 1 + epsilon for fractional_odd when any outer level exceeds 1,
  // so that a ring exists to stitch the outer edges to ("treated as though it were originally
  // specified as 1 + epsilon", 11.2.2.1).
  Range inner_range(bool any_level_above_one) const {
    Range r = range;
    if (spacing == TessSpacing::FractionalOdd && any_level_above_one)
      r.lo = 1.0f + 1.0f / float(kTessOne);
    return r;
  }
  bool above_one(float clamped) const {
    // llvmpipe tests against 1 + 2^-17: levels that will round to 1 in 16.16 do not count.
    const float threshold =
        profile->odd_level_collapses_near_one ? 1.0f + 0.5f / float(kTessOne) : 1.0f;
    return clamped > threshold;
  }
  Parity inner_parity(float clamped) const {
    // Equal spacing treats an inner level of 1 as even (two segments once outer levels exceed 1).
    if (spacing == TessSpacing::Equal && clamped == 1.0f) return Parity::Even;
    return parity(clamped);
  }
  // "all levels one" gives the single-primitive patch (equal and fractional_odd only).
  bool minimum_allowed() const { return spacing != TessSpacing::FractionalEven; }

  // Clamps, rounds and converts `count` outer levels; returns whether any ends up above one.
  bool process_outer(const std::array<float, 4>& raw, int count, Fx16* fx, Parity* parity) const {
    bool any_above_one = false;
    for (int e = 0; e < count; ++e) {
      const float c = clamp_outer(raw[e]);
      any_above_one |= above_one(c);
      fx[e] = to_fixed(c);
      parity[e] = this->parity(c);
    }
    return any_above_one;
  }
  // The inner level after the 1 + epsilon rule, clamping and (equal spacing) rounding up.
  void process_inner(float raw, bool any_above_one, Fx16& fx, Parity& parity) const {
    float inner = clamp_level(raw, inner_range(any_above_one));
    if (spacing == TessSpacing::Equal) inner = std::ceil(inner);
    fx = to_fixed(inner);
    parity = inner_parity(inner);
  }
};

void emit_points_only(tpg::DomainOutput& d, TessDomainPoints& out) {
  out.indices.resize(d.points.size());
  for (std::size_t i = 0; i < d.points.size(); ++i) out.indices[i] = std::uint32_t(i);
}

}  // namespace

void generate_tessellation(const TessLayout& layout, const TessLevels& levels,
                           const TessProfile& profile, TessDomainPoints& out) {
  out.coords.clear();
  out.indices.clear();
  out.discarded = false;
  out.vertices_per_primitive =
      layout.point_mode ? 1 : (layout.domain == TessDomain::Isolines ? 2 : 3);

  const int max_level = std::clamp(profile.max_level, 2, 64);
  const LevelRules rules{layout.spacing, clamp_range(layout.spacing, max_level), &profile};
  const bool reverse = layout.winding == TessWinding::Cw;
  const bool connect = !layout.point_mode;
  tpg::DomainOutput d;

  switch (layout.domain) {
    case TessDomain::Triangles: {
      if (discards(levels.outer[0]) || discards(levels.outer[1]) || discards(levels.outer[2])) {
        out.discarded = true;
        return;
      }
      tpg::TriangleLevels lv;
      const bool any_above_one = rules.process_outer(levels.outer, 3, lv.outer, lv.outer_parity);
      rules.process_inner(levels.inner[0], any_above_one, lv.inner, lv.inner_parity);
      if (rules.minimum_allowed() && lv.inner == kTessOne && lv.outer[0] == kTessOne &&
          lv.outer[1] == kTessOne && lv.outer[2] == kTessOne) {
        // A single triangle: the v = 1, w = 1 and u = 1 corners.
        d.points = {{0, kTessOne}, {0, 0}, {kTessOne, 0}};
        if (connect) tpg::TriangleSink{&d.indices, reverse}(0, 1, 2);
      } else {
        tpg::generate_triangles(lv, reverse, connect, d);
      }
      break;
    }
    case TessDomain::Quads: {
      for (int e = 0; e < 4; ++e) {
        if (discards(levels.outer[e])) {
          out.discarded = true;
          return;
        }
      }
      tpg::QuadLevels lv;
      bool any_above_one = rules.process_outer(levels.outer, 4, lv.outer, lv.outer_parity);
      // Quads also look at the (raw) inner levels when deciding on the 1 + epsilon frame.
      for (int a = 0; a < 2; ++a) any_above_one |= rules.above_one(levels.inner[a]);
      bool all_one = true;
      for (int a = 0; a < 2; ++a) {
        rules.process_inner(levels.inner[a], any_above_one, lv.inner[a], lv.inner_parity[a]);
        all_one &= lv.inner[a] == kTessOne;
      }
      for (int e = 0; e < 4; ++e) all_one &= lv.outer[e] == kTessOne;
      if (rules.minimum_allowed() && all_one) {
        d.points = {{0, 0}, {kTessOne, 0}, {kTessOne, kTessOne}, {0, kTessOne}};
        if (connect) {
          const tpg::TriangleSink emit{&d.indices, reverse};
          emit(0, 1, 3);
          emit(1, 2, 3);
        }
      } else {
        tpg::generate_quads(lv, reverse, connect, d);
      }
      break;
    }
    case TessDomain::Isolines: {
      // "outer[0]: the number of lines, outer[1]: segments per line; the patch is discarded if
      // either is <= 0 or NaN. The number of lines is always subdivided with equal spacing."
      if (discards(levels.outer[0]) || discards(levels.outer[1])) {
        out.discarded = true;
        return;
      }
      tpg::IsolineLevels lv;
      const float density = std::ceil(clamp_level(levels.outer[0], {1.0f, float(max_level)}));
      lv.density = tess_from_float(density);
      lv.density_parity = parity_of_integer(density);
      const float detail = rules.clamp_outer(levels.outer[1]);
      lv.detail = rules.to_fixed(detail);
      lv.detail_parity = rules.parity(detail);
      tpg::generate_isolines(lv, connect, d);
      break;
    }
  }

  out.coords.reserve(d.points.size());
  for (const tpg::FxPoint& p : d.points) {
    const float u = tess_to_float(p.u), v = tess_to_float(p.v);
    // Triangles: w = (1 - u) - v in float, exact since u and v are multiples of 2^-16.
    const float w = layout.domain == TessDomain::Triangles ? (1.0f - u) - v : 0.0f;
    out.coords.emplace_back(u, v, w);
  }
  if (connect) out.indices = std::move(d.indices);
  else emit_points_only(d, out);
}

TessDomainPoints generate_tessellation(const TessLayout& layout, const TessLevels& levels,
                                       const TessProfile& profile) {
  TessDomainPoints out;
  generate_tessellation(layout, levels, profile, out);
  return out;
}

// What generate_tessellation computes before the domain generators, through the same LevelRules
// (tpg_levels.h). The segment counts are those of the subdivision each domain generator makes.
ProcessedTessLevels process_tess_levels(const TessLayout& layout, const TessLevels& levels,
                                        const TessProfile& profile) {
  ProcessedTessLevels out;
  const int max_level = std::clamp(profile.max_level, 2, 64);
  const LevelRules rules{layout.spacing, clamp_range(layout.spacing, max_level), &profile};
  auto segments = [](Fx16 fx, Parity parity) { return tpg::make_subdivision(fx, parity).num_points - 1; };
  const int outer_count = layout.domain == TessDomain::Triangles ? 3 : layout.domain == TessDomain::Quads ? 4 : 2;
  out.outer_count = outer_count;
  out.inner_count = layout.domain == TessDomain::Triangles ? 1 : layout.domain == TessDomain::Quads ? 2 : 0;
  for (int e = 0; e < outer_count; ++e) out.discarded |= discards(levels.outer[e]);
  if (out.discarded) return out;

  if (layout.domain == TessDomain::Isolines) {
    const float density = std::ceil(clamp_level(levels.outer[0], {1.0f, float(max_level)}));
    const float detail = rules.clamp_outer(levels.outer[1]);
    out.outer = {density, detail, 0.0f, 0.0f};
    out.outer_segments[0] = int(density);  // lines, not segments: the lines at v = 0 .. < 1
    out.outer_segments[1] = segments(rules.to_fixed(detail), rules.parity(detail));
    return out;
  }
  Fx16 fx[4];
  Parity parity[4];
  bool any_above_one = rules.process_outer(levels.outer, outer_count, fx, parity);
  for (int e = 0; e < outer_count; ++e) {
    out.outer[e] = rules.clamp_outer(levels.outer[e]);
    out.outer_segments[e] = segments(fx[e], parity[e]);
  }
  // Quads also look at the raw inner levels for the 1 + epsilon frame (as generate_tessellation).
  if (layout.domain == TessDomain::Quads)
    for (int a = 0; a < 2; ++a) any_above_one |= rules.above_one(levels.inner[a]);
  for (int a = 0; a < out.inner_count; ++a) {
    Fx16 inner_fx;
    Parity inner_parity;
    rules.process_inner(levels.inner[a], any_above_one, inner_fx, inner_parity);
    float inner = clamp_level(levels.inner[a], rules.inner_range(any_above_one));
    if (layout.spacing == TessSpacing::Equal) inner = std::ceil(inner);
    out.inner[a] = inner;
    out.inner_segments[a] = segments(inner_fx, inner_parity);
  }
  return out;
}

}  // namespace tessref
