// Property tests of what the GL 4.6 spec fixes about the primitive generator (11.2.2, A.4), over
// 10,000 random level sets per domain and spacing (fixed seeds).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <set>

#include "stages/tpg.h"
#include "stages/tpg_stream.h"
#include "tpg_test_util.h"

namespace tessref {
namespace {

using test::expected_segments;
using test::random_levels;

constexpr int kSets = 10000;
constexpr TessSpacing kSpacings[] = {TessSpacing::Equal, TessSpacing::FractionalOdd,
                                     TessSpacing::FractionalEven};

bool on_edge(TessDomain d, int e, glm::vec3 c) {
  if (d == TessDomain::Triangles) return c[e] == 0.0f;  // edge e: the coordinate e is zero
  switch (e) {
    case 0: return c.x == 0.0f;
    case 1: return c.y == 0.0f;
    case 2: return c.x == 1.0f;
    default: return c.y == 1.0f;
  }
}
// The parameter along an edge, oriented the same way for every edge (its value at the edge's
// starting corner in emission order is 1 for edges walked "downwards", see edge_points).
float edge_param(TessDomain d, int e, glm::vec3 c) {
  if (d == TessDomain::Triangles) return e == 0 ? c.y : c.x;
  return (e & 1) ? c.x : c.y;
}

int outer_edges(TessDomain d) { return d == TessDomain::Triangles ? 3 : 4; }

// The parameters of the generated points on outer edge e, sorted: the edge's slice of the outer
// ring (emitted first, one edge after the other, each leaving out its end corner) plus that corner.
std::vector<float> edge_points(const TessDomainPoints& p, TessDomain d, int e,
                               const std::array<int, 4>& segments) {
  int start = 0;
  for (int k = 0; k < e; ++k) start += segments[k];
  const int ring = [&] {
    int r = 0;
    for (int k = 0; k < outer_edges(d); ++k) r += segments[k];
    return r;
  }();
  std::vector<float> t;
  for (int k = 0; k <= segments[e]; ++k) {
    const glm::vec3 c = p.coords[(start + k) % ring];
    EXPECT_TRUE(on_edge(d, e, c)) << "edge " << e << " point " << k;
    t.push_back(edge_param(d, e, c));
  }
  std::sort(t.begin(), t.end());
  return t;
}

TessLayout layout_of(TessDomain d, TessSpacing s, TessWinding w = TessWinding::Ccw,
                     bool point_mode = false) {
  return TessLayout{d, s, w, point_mode};
}

class TpgRules : public ::testing::TestWithParam<std::tuple<TessDomain, TessSpacing>> {};
// The rules about outer edges and triangles: the triangle and quad domains.
class TpgSurfaceRules : public TpgRules {};

// Discard (11.2.2), the segment count of every outer edge (rounding and clamping per spacing),
// rules 2-4 (an edge's points depend only on its level and spacing, whichever edge, and are
// symmetric), rule 8 (components in [0, 1], 1 - x exact), and rule 1 (same input, same output).
TEST_P(TpgRules, OuterEdgesFollowTheSpec) {
  const auto [domain, spacing] = GetParam();
  std::mt19937 rng(1234 + int(domain) * 10 + int(spacing));
  const int edges = outer_edges(domain);
  std::map<int, std::vector<float>> canonical;  // segments -> edge parameters
  int checked = 0;
  for (int n = 0; n < kSets; ++n) {
    const TessLevels levels = random_levels(rng);
    const TessLayout layout = layout_of(domain, spacing);
    const TessDomainPoints p = generate_tessellation(layout, levels);
    bool discard = false;
    for (int e = 0; e < (domain == TessDomain::Isolines ? 2 : edges); ++e)
      discard |= !(levels.outer[e] > 0.0f);
    ASSERT_EQ(p.discarded, discard);
    if (discard) {
      ASSERT_TRUE(p.coords.empty() && p.indices.empty());
      continue;
    }
    const TessDomainPoints again = generate_tessellation(layout, levels);
    ASSERT_EQ(emitted_stream(p), emitted_stream(again));  // rule 1

    for (const glm::vec3& c : p.coords) {
      for (int k = 0; k < 3; ++k) {
        ASSERT_GE(c[k], 0.0f);
        ASSERT_LE(c[k], 1.0f);
        ASSERT_EQ(c[k] * 65536.0f, std::floor(c[k] * 65536.0f));  // llvmpipe: 16.16 coordinates
      }
      if (domain == TessDomain::Triangles) {
        ASSERT_EQ(c.z, (1.0f - c.x) - c.y);
        ASSERT_EQ(double(c.x) + double(c.y) + double(c.z), 1.0);
      }
    }

    if (domain == TessDomain::Isolines) {
      // outer[0] lines at v = k / lines (equal spacing), outer[1] segments per line.
      const int lines = expected_segments(levels.outer[0], TessSpacing::Equal);
      const int segments = expected_segments(levels.outer[1], spacing);
      ASSERT_EQ(p.coords.size(), std::size_t(lines * (segments + 1)));
      ASSERT_EQ(p.primitive_count(), std::size_t(lines * segments));
      for (int line = 0; line < lines; ++line) {
        std::vector<float> t;
        for (int k = 0; k <= segments; ++k) {
          const glm::vec3 c = p.coords[line * (segments + 1) + k];
          ASSERT_EQ(c.y, p.coords[line * (segments + 1)].y);
          t.push_back(c.x);
        }
        ASSERT_EQ(t.front(), 0.0f);
        ASSERT_EQ(t.back(), 1.0f);
        for (std::size_t k = 0; k < t.size(); ++k) ASSERT_EQ(t[k], 1.0f - t[t.size() - 1 - k]);
      }
      ++checked;
      continue;
    }
    std::array<int, 4> segments{};
    bool all_one = true;
    for (int e = 0; e < edges; ++e) {
      segments[e] = expected_segments(levels.outer[e], spacing);
      all_one &= segments[e] == 1;
    }
    if (all_one) continue;  // the single-primitive patch has no ring structure to slice
    for (int e = 0; e < edges; ++e) {
      const std::vector<float> t = edge_points(p, domain, e, segments);
      ASSERT_EQ(t.front(), 0.0f);
      ASSERT_EQ(t.back(), 1.0f);
      for (std::size_t k = 0; k < t.size(); ++k) ASSERT_EQ(t[k], 1.0f - t[t.size() - 1 - k]);
      auto [it, fresh] = canonical.emplace(segments[e], t);
      if (!fresh) {
        // Same segment count, same spacing: the same points (levels may differ in their fraction
        // only for equal spacing, where the count is all that matters).
        if (spacing == TessSpacing::Equal) {
          ASSERT_EQ(it->second, t) << "edge " << e;
        }
      }
    }
    ++checked;
  }
  EXPECT_GT(checked, kSets / 2);
}

// Rule 2 for fractional spacing: the points on an edge depend on its level only, so the same
// level on any edge of any patch (and any domain) gives the same points.
TEST_P(TpgSurfaceRules, EdgePointsDependOnlyOnTheirLevel) {
  const auto [domain, spacing] = GetParam();
  std::mt19937 rng(99 + int(domain) * 10 + int(spacing));
  const int edges = outer_edges(domain);
  for (int n = 0; n < kSets / 10; ++n) {
    TessLevels a = random_levels(rng);
    for (int e = 0; e < 4; ++e) a.outer[e] = std::uniform_real_distribution<float>(1.5f, 64.f)(rng);
    TessLevels b = random_levels(rng);
    for (int e = 0; e < 4; ++e) b.outer[e] = std::uniform_real_distribution<float>(1.5f, 64.f)(rng);
    const int ea = n % edges, eb = (n / 3) % edges;
    b.outer[eb] = a.outer[ea];
    const TessLayout layout = layout_of(domain, spacing);
    const TessDomainPoints pa = generate_tessellation(layout, a), pb = generate_tessellation(layout, b);
    std::array<int, 4> sa{}, sb{};
    for (int e = 0; e < edges; ++e) {
      sa[e] = expected_segments(a.outer[e], spacing);
      sb[e] = expected_segments(b.outer[e], spacing);
    }
    ASSERT_EQ(edge_points(pa, domain, ea, sa), edge_points(pb, domain, eb, sb))
        << "level " << a.outer[ea] << " edges " << ea << "/" << eb;
  }
}

// Rule 5: the vertex order changes the orientation of each triangle, not the set of triangles.
// Rules 6 and 7: interior triangles depend only on the inner levels, and the triangles joining an
// outer edge to the inner ring only on that edge's level and the inner levels.
TEST_P(TpgSurfaceRules, WindingInteriorAndTransitionInvariance) {
  const auto [domain, spacing] = GetParam();
  std::mt19937 rng(7 + int(domain) * 10 + int(spacing));
  using Tri = std::array<std::array<float, 3>, 3>;
  auto canonical = [](glm::vec3 a, glm::vec3 b, glm::vec3 c, bool flip) {
    Tri t{{{a.x, a.y, a.z}, {b.x, b.y, b.z}, {c.x, c.y, c.z}}};
    if (flip) std::swap(t[1], t[2]);
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return t;
  };
  auto triangles = [&](const TessDomainPoints& p, bool flip) {
    std::multiset<Tri> s;
    for (std::size_t i = 0; i < p.indices.size(); i += 3)
      s.insert(canonical(p.coords[p.indices[i]], p.coords[p.indices[i + 1]],
                         p.coords[p.indices[i + 2]], flip));
    return s;
  };
  const int edges = outer_edges(domain);
  auto boundary_edges = [&](const Tri& t) {
    std::set<int> on;
    for (const auto& v : t) {
      const glm::vec3 c(v[0], v[1], v[2]);
      int count = 0, which = -1;
      for (int e = 0; e < edges; ++e)
        if (on_edge(domain, e, c)) ++count, which = e;
      if (count == 1) on.insert(which);  // an open edge point (corners lie on two edges)
      if (count >= 1) on.insert(-1);     // touches the boundary
    }
    return on;
  };
  for (int n = 0; n < kSets / 10; ++n) {
    TessLevels a = random_levels(rng);
    for (int e = 0; e < 4; ++e) a.outer[e] = std::uniform_real_distribution<float>(0.6f, 66.f)(rng);
    for (int i = 0; i < 2; ++i) a.inner[i] = std::uniform_real_distribution<float>(2.0f, 66.f)(rng);
    const TessLayout ccw = layout_of(domain, spacing);
    const TessLayout cw = layout_of(domain, spacing, TessWinding::Cw);
    const TessDomainPoints pa = generate_tessellation(ccw, a);
    ASSERT_EQ(triangles(pa, false), triangles(generate_tessellation(cw, a), true));  // rule 5

    TessLevels b = a;
    const int keep = n % edges;
    for (int e = 0; e < edges; ++e)
      if (e != keep) b.outer[e] = std::uniform_real_distribution<float>(0.6f, 66.f)(rng);
    const TessDomainPoints pb = generate_tessellation(ccw, b);
    std::multiset<Tri> interior_a, interior_b, strip_a, strip_b;
    for (const Tri& t : triangles(pa, false)) {
      const auto on = boundary_edges(t);
      if (on.empty()) interior_a.insert(t);
      else if (on.count(keep) && on.size() == 2) strip_a.insert(t);
    }
    for (const Tri& t : triangles(pb, false)) {
      const auto on = boundary_edges(t);
      if (on.empty()) interior_b.insert(t);
      else if (on.count(keep) && on.size() == 2) strip_b.insert(t);
    }
    ASSERT_EQ(interior_a, interior_b) << "rule 6, set " << n;  // rule 6
    ASSERT_EQ(strip_a, strip_b) << "rule 7, set " << n;        // rule 7
  }
}

INSTANTIATE_TEST_SUITE_P(
    AllSpacings, TpgRules,
    ::testing::Combine(::testing::Values(TessDomain::Triangles, TessDomain::Quads,
                                         TessDomain::Isolines),
                       ::testing::ValuesIn(kSpacings)),
    [](const auto& info) {
      return std::string(to_string(std::get<0>(info.param))) + "_" +
             to_string(std::get<1>(info.param));
    });

INSTANTIATE_TEST_SUITE_P(
    SurfaceDomains, TpgSurfaceRules,
    ::testing::Combine(::testing::Values(TessDomain::Triangles, TessDomain::Quads),
                       ::testing::ValuesIn(kSpacings)),
    [](const auto& info) {
      return std::string(to_string(std::get<0>(info.param))) + "_" +
             to_string(std::get<1>(info.param));
    });

// Clamping (11.2.2): levels past the maximum act as the maximum; NaN and negative inner levels
// clamp to the minimum and do not discard; equal spacing rounds up.
TEST(TpgClamp, ClampAndRoundEquivalences) {
  std::mt19937 rng(42);
  for (TessSpacing s : kSpacings) {
    for (TessDomain d : {TessDomain::Triangles, TessDomain::Quads, TessDomain::Isolines}) {
      const TessLayout layout = layout_of(d, s);
      const float max_level = s == TessSpacing::FractionalOdd ? 63.0f : 64.0f;
      for (int n = 0; n < 2000; ++n) {
        TessLevels l = random_levels(rng);
        for (float& o : l.outer) o = std::uniform_real_distribution<float>(0.5f, 70.f)(rng);
        const auto reference = emitted_stream(generate_tessellation(layout, l));
        TessLevels big = l;
        big.outer[n % 4] = l.outer[n % 4] >= max_level ? 1e30f : l.outer[n % 4];
        big.inner[n % 2] = l.inner[n % 2] >= max_level ? INFINITY : l.inner[n % 2];
        ASSERT_EQ(reference, emitted_stream(generate_tessellation(layout, big)));
        if (s == TessSpacing::Equal) {
          TessLevels up = l;
          for (float& o : up.outer) o = std::ceil(std::fmin(64.0f, o));
          for (float& i : up.inner) i = std::ceil(std::fmin(64.0f, std::fmax(1.0f, i)));
          if (std::isnan(l.inner[0]) || std::isnan(l.inner[1])) continue;
          ASSERT_EQ(reference, emitted_stream(generate_tessellation(layout, up)));
        }
        TessLevels low_inner = l;
        low_inner.inner = {-3.0f, NAN};
        TessLevels min_inner = l;
        min_inner.inner = {1.0f, 1.0f};
        const TessDomainPoints li = generate_tessellation(layout, low_inner);
        ASSERT_FALSE(li.discarded);
        ASSERT_EQ(emitted_stream(li), emitted_stream(generate_tessellation(layout, min_inner)));
      }
    }
  }
}

TEST(TpgClamp, MaxLevelIsConfigurable) {
  TessProfile p16;
  p16.max_level = 16;
  const TessLayout layout = layout_of(TessDomain::Triangles, TessSpacing::Equal);
  TessLevels a, b;
  a.outer = {40, 40, 40, 0};
  a.inner = {40, 0};
  b.outer = {16, 16, 16, 0};
  b.inner = {16, 0};
  EXPECT_EQ(emitted_stream(generate_tessellation(layout, a, p16)),
            emitted_stream(generate_tessellation(layout, b)));
}

}  // namespace
}  // namespace tessref
