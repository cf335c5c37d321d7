// Capturing llvmpipe's primitive generator: facts measured on Mesa 22.3.6 llvmpipe, batching,
// the 65,535-vertex split, and the structure every capture must have.
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "gl_fixture.h"
#include "glref/gl_error.h"
#include "glref/tess_capture.h"

namespace tessref::glref {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

TessLevels uniform_levels(float v) {
  TessLevels l;
  l.outer = {v, v, v, v};
  l.inner = {v, v};
  return l;
}

TessLayout layout_of(TessDomain d, TessSpacing s, TessWinding w = TessWinding::Ccw, bool points = false) {
  TessLayout l;
  l.domain = d;
  l.spacing = s;
  l.winding = w;
  l.point_mode = points;
  return l;
}

bool bit_equal(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(glm::vec3)) == 0);
}

std::string describe(const TessLevels& l) {
  char buf[200];
  std::snprintf(buf, sizeof buf, "outer %a %a %a %a inner %a %a", l.outer[0], l.outer[1], l.outer[2],
                l.outer[3], l.inner[0], l.inner[1]);
  return buf;
}

// Levels that exercise every path: integers, fractions, the clamps, 64, just above 1, and values
// that discard (outer <= 0, NaN) or clamp (inner NaN, negative, infinite).
std::vector<TessLevels> random_levels(std::size_t n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> any(0.0f, 70.0f);
  std::uniform_int_distribution<int> pick(0, 19);
  const float specials[] = {64.0f, 64.0f, 1.0f, 2.0f, 63.5f, 1.0f + 0x1p-17f, 1.0f + 0x1p-15f,
                            kInf, -1.0f, 0.0f, kNaN, 0.25f, 100.0f};
  auto level = [&] {
    const int k = pick(rng);
    if (k < 8) return any(rng);
    if (k < 11) return std::floor(any(rng)) + 1.0f;
    return specials[(k - 11 + rng()) % std::size(specials)];
  };
  std::vector<TessLevels> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (float& o : out[i].outer) o = level();
    for (float& v : out[i].inner) v = level();
    // Mostly keep patches alive: a discard on every fifth would leave too little geometry.
    if (i % 5 != 0)
      for (float& o : out[i].outer)
        if (!(o > 0.0f)) o = 64.0f;
  }
  // Level-64 patches throughout, so the batch needs several draws.
  for (std::size_t i = 0; i < n; i += 7) out[i] = uniform_levels(64.0f);
  return out;
}

TEST(TessCapture, FractionalOddAllFourGives37Triangles) {
  TESSREF_REQUIRE_GL(ctx);
  if (!ctx->is_llvmpipe()) GTEST_SKIP() << "measured on llvmpipe; renderer is " << ctx->renderer();
  const auto r = capture_tess_coords(*ctx, layout_of(TessDomain::Triangles, TessSpacing::FractionalOdd),
                                     {uniform_levels(4.0f)});
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].size(), 111u);  // 37 triangles
  const float expected = 48060.0f / 65536.0f;
  EXPECT_EQ(expected, 0.733337402f);
  bool found = false;
  for (const glm::vec3& c : r[0])
    for (int k = 0; k < 3; ++k) found |= c[k] == expected;
  EXPECT_TRUE(found);
}

TEST(TessCapture, EqualAllOneIsOneTriangle) {
  TESSREF_REQUIRE_GL(ctx);
  const auto r = capture_tess_coords(*ctx, layout_of(TessDomain::Triangles, TessSpacing::Equal),
                                     {uniform_levels(1.0f)});
  ASSERT_EQ(r[0].size(), 3u);
  // The corners in some order; llvmpipe emits (0,1,0), (0,0,1), (1,0,0) with ccw.
  std::vector<glm::vec3> sorted = r[0];
  std::sort(sorted.begin(), sorted.end(), [](auto a, auto b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); });
  EXPECT_EQ(sorted, (std::vector<glm::vec3>{{0, 0, 1}, {0, 1, 0}, {1, 0, 0}}));
  if (ctx->is_llvmpipe()) {
    EXPECT_EQ(r[0], (std::vector<glm::vec3>{{0, 1, 0}, {0, 0, 1}, {1, 0, 0}}));
  }
}

// The smallest patch of each kind, in llvmpipe's emission order (measured, Mesa 22.3.6).
TEST(TessCapture, SmallestPatchesInLlvmpipeOrder) {
  TESSREF_REQUIRE_GL(ctx);
  if (!ctx->is_llvmpipe()) GTEST_SKIP() << "measured on llvmpipe; renderer is " << ctx->renderer();
  using V = std::vector<glm::vec3>;
  const TessLevels ones = uniform_levels(1.0f);
  auto one = [&](TessLayout l) { return capture_tess_coords(*ctx, l, {ones})[0]; };
  EXPECT_EQ(one(layout_of(TessDomain::Triangles, TessSpacing::Equal, TessWinding::Cw)),
            (V{{0, 1, 0}, {1, 0, 0}, {0, 0, 1}}));
  EXPECT_EQ(one(layout_of(TessDomain::Triangles, TessSpacing::Equal, TessWinding::Ccw, true)),
            (V{{0, 1, 0}, {0, 0, 1}, {1, 0, 0}}));
  EXPECT_EQ(one(layout_of(TessDomain::Quads, TessSpacing::Equal)),
            (V{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}));
  EXPECT_EQ(one(layout_of(TessDomain::Isolines, TessSpacing::Equal)), (V{{0, 0, 0}, {1, 0, 0}}));
}

TEST(TessCapture, CwReversesEachTriangleOfCcw) {
  TESSREF_REQUIRE_GL(ctx);
  const TessLevels l = uniform_levels(3.0f);
  const auto ccw = capture_tess_coords(*ctx, layout_of(TessDomain::Triangles, TessSpacing::Equal), {l});
  const auto cw = capture_tess_coords(*ctx, layout_of(TessDomain::Triangles, TessSpacing::Equal, TessWinding::Cw), {l});
  ASSERT_EQ(ccw[0].size(), cw[0].size());
  // Same triangles; the orientation of each is opposite (sign of the uv-area).
  for (std::size_t t = 0; t + 2 < ccw[0].size(); t += 3) {
    auto area = [](const std::vector<glm::vec3>& v, std::size_t i) {
      const glm::vec2 a(v[i]), b(v[i + 1]), c(v[i + 2]);
      return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    };
    EXPECT_LT(area(ccw[0], t) * area(cw[0], t), 0.0f) << "triangle " << t / 3;
  }
}

TEST(TessCapture, DiscardedPatchesEmitNothingAndLeaveNeighboursAlone) {
  TESSREF_REQUIRE_GL(ctx);
  const TessLayout layout = layout_of(TessDomain::Triangles, TessSpacing::FractionalOdd);
  TessLevels live = uniform_levels(5.5f);
  TessLevels zero = live, nan = live, neg = live, last_edge = live;
  zero.outer[0] = 0.0f;
  nan.outer[0] = kNaN;
  neg.outer[0] = -1.0f;
  last_edge.outer[2] = -0.42f;
  TessLevels fourth_ignored = live;  // outer[3] is not a triangle level
  fourth_ignored.outer[3] = -1.0f;
  const std::vector<TessLevels> batch = {live, zero, live, nan, live, neg, live, last_edge, fourth_ignored};
  TessCapture capture(*ctx);
  const auto r = capture.capture(layout, batch);
  const auto alone = capture.capture(layout, {live});
  ASSERT_FALSE(alone[0].empty());
  for (std::size_t i : {1, 3, 5, 7}) EXPECT_TRUE(r[i].empty()) << "patch " << i;
  for (std::size_t i : {0, 2, 4, 6, 8}) EXPECT_TRUE(bit_equal(r[i], alone[0])) << "patch " << i;
}

TEST(TessCapture, QuadAndIsolineDiscardUseTheirOwnOuterLevels) {
  TESSREF_REQUIRE_GL(ctx);
  TessLevels l = uniform_levels(3.0f);
  l.outer[3] = 0.0f;
  EXPECT_TRUE(capture_tess_coords(*ctx, layout_of(TessDomain::Quads, TessSpacing::Equal), {l})[0].empty());
  EXPECT_FALSE(capture_tess_coords(*ctx, layout_of(TessDomain::Isolines, TessSpacing::Equal), {l})[0].empty());
  l.outer[1] = kNaN;
  EXPECT_TRUE(capture_tess_coords(*ctx, layout_of(TessDomain::Isolines, TessSpacing::Equal), {l})[0].empty());
}

TEST(TessCapture, EmptyInputGivesEmptyOutput) {
  TESSREF_REQUIRE_GL(ctx);
  EXPECT_TRUE(capture_tess_coords(*ctx, TessLayout{}, {}).empty());
}

struct LayoutCase {
  TessLayout layout;
  std::size_t alone_checked;  // how many of the 500 are also captured one by one
};

class BatchInvariance : public ::testing::TestWithParam<LayoutCase> {};

// 500 random level sets in one call equal each captured alone, bit for bit. The batch holds
// level-64 patches, so it spans several draws each below Mesa's 65,535-vertex limit; a wrap
// would tag vertices with other patches and fail inside capture().
TEST_P(BatchInvariance, OneCallEqualsOnePatchAtATime) {
  TESSREF_REQUIRE_GL(ctx);
  const TessLayout layout = GetParam().layout;
  const std::vector<TessLevels> levels = random_levels(500, 1234u + static_cast<unsigned>(layout.domain) * 10 +
                                                                static_cast<unsigned>(layout.spacing));
  TessCapture capture(*ctx);
  const auto batch = capture.capture(layout, levels);
  const CaptureStats stats = capture.last_stats();
  ASSERT_EQ(batch.size(), levels.size());
  EXPECT_GT(stats.draws, 2u);
  std::size_t point_bound = 0;
  for (const TessLevels& l : levels) point_bound += domain_point_bound(layout, l);
  EXPECT_GT(point_bound, 65535u * 2);  // the split is exercised

  const std::size_t step = levels.size() / GetParam().alone_checked;
  for (std::size_t i = 0; i < levels.size(); i += step) {
    const auto alone = capture.capture(layout, {levels[i]});
    ASSERT_TRUE(bit_equal(batch[i], alone[0])) << "patch " << i << ": " << describe(levels[i]) << " batch "
                                               << batch[i].size() << " vertices, alone " << alone[0].size();
  }
  // Discard follows the spec: empty exactly when a relevant outer level is <= 0 or NaN.
  for (std::size_t i = 0; i < levels.size(); ++i)
    EXPECT_EQ(batch[i].empty(), domain_point_bound(layout, levels[i]) == 0) << "patch " << i << ": " << describe(levels[i]);
}

// Every captured coordinate is in [0,1]; vertices per primitive divide the count; quads and
// isolines have z == 0. On llvmpipe (16.16 fixed point inside) every coordinate is a multiple of
// 2^-16 and triangles have z == (1 - x) - y in float.
TEST_P(BatchInvariance, CoordinatesAreFixedPointAndConsistent) {
  TESSREF_REQUIRE_GL(ctx);
  const bool fixed_point = ctx->is_llvmpipe();
  const TessLayout layout = GetParam().layout;
  const auto batch = capture_tess_coords(*ctx, layout, random_levels(200, 99u));
  const int vpp = vertices_per_primitive(layout);
  for (std::size_t p = 0; p < batch.size(); ++p) {
    ASSERT_EQ(batch[p].size() % vpp, 0u) << "patch " << p;
    for (const glm::vec3& c : batch[p]) {
      for (int k = 0; k < 2; ++k) {
        ASSERT_GE(c[k], 0.0f);
        ASSERT_LE(c[k], 1.0f);
        const float scaled = c[k] * 65536.0f;
        if (fixed_point) {
          ASSERT_EQ(scaled, std::floor(scaled)) << "patch " << p << " component " << k << " = " << c[k];
        }
      }
      if (layout.domain == TessDomain::Triangles && fixed_point)
        ASSERT_EQ(c.z, (1.0f - c.x) - c.y) << "patch " << p;
      else
        ASSERT_EQ(c.z, 0.0f) << "patch " << p;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Layouts, BatchInvariance,
    ::testing::Values(LayoutCase{layout_of(TessDomain::Triangles, TessSpacing::FractionalOdd), 500},
                      LayoutCase{layout_of(TessDomain::Triangles, TessSpacing::FractionalEven, TessWinding::Cw), 100},
                      LayoutCase{layout_of(TessDomain::Triangles, TessSpacing::Equal), 100},
                      LayoutCase{layout_of(TessDomain::Quads, TessSpacing::Equal), 100},
                      LayoutCase{layout_of(TessDomain::Quads, TessSpacing::FractionalOdd, TessWinding::Cw), 100},
                      LayoutCase{layout_of(TessDomain::Isolines, TessSpacing::FractionalEven), 100},
                      LayoutCase{layout_of(TessDomain::Triangles, TessSpacing::FractionalOdd, TessWinding::Ccw, true), 100},
                      LayoutCase{layout_of(TessDomain::Quads, TessSpacing::Equal, TessWinding::Cw, true), 100}),
    [](const ::testing::TestParamInfo<LayoutCase>& info) {
      const TessLayout& l = info.param.layout;
      return std::string(to_string(l.domain)) + "_" + to_string(l.spacing) + "_" + to_string(l.winding) +
             (l.point_mode ? "_points" : "");
    });

// The trap the split avoids: one llvmpipe draw of more than 65,535 tessellated vertices mixes up
// patches without any GL error. capture() must notice (patch ids), never return the garbage.
// A level-64 triangle patch has 3,169 domain points: 20 in one draw (63,380) are fine, 21
// (66,549) wrap.
TEST(TessCapture, DetectsMesaVertexIndexWrapWhenNotSplit) {
  TESSREF_REQUIRE_GL(ctx);
  if (!ctx->is_llvmpipe()) GTEST_SKIP() << "the wrap is llvmpipe's; renderer is " << ctx->renderer();
  CaptureOptions unsplit;
  unsplit.max_points_per_draw = std::numeric_limits<std::size_t>::max();
  TessCapture capture(*ctx, unsplit);
  const std::vector<TessLevels> twenty(20, uniform_levels(64.0f));
  const auto r20 = capture.capture(TessLayout{}, twenty);
  EXPECT_EQ(capture.last_stats().draws, 1u);
  std::vector<TessLevels> twenty_one = twenty;
  twenty_one.push_back(twenty[0]);
  try {
    capture.capture(TessLayout{}, twenty_one);
    FAIL() << "a 66,549-point draw was not caught";
  } catch (const GlError& e) {
    EXPECT_NE(std::string(e.what()).find("mixed up patches"), std::string::npos) << e.what();
  }
  // Split (the default), the same patches are all identical to a single one.
  TessCapture split(*ctx);
  const auto r = split.capture(TessLayout{}, std::vector<TessLevels>(60, twenty[0]));
  EXPECT_GE(split.last_stats().draws, 4u);
  for (std::size_t i = 0; i < r.size(); ++i) ASSERT_TRUE(bit_equal(r[i], r20[0])) << "patch " << i;
  for (std::size_t i = 0; i < r20.size(); ++i) ASSERT_TRUE(bit_equal(r20[i], r20[0])) << "patch " << i;
}

TEST(TessCapture, UploadSlicesGiveTheSameResult) {
  TESSREF_REQUIRE_GL(ctx);
  const TessLayout layout = layout_of(TessDomain::Quads, TessSpacing::FractionalEven);
  const auto levels = random_levels(300, 7u);
  CaptureOptions sliced;
  sliced.max_patches_per_upload = 37;
  TessCapture a(*ctx), b(*ctx, sliced);
  const auto ra = a.capture(layout, levels);
  const auto rb = b.capture(layout, levels);
  ASSERT_EQ(ra.size(), rb.size());
  for (std::size_t i = 0; i < ra.size(); ++i) ASSERT_TRUE(bit_equal(ra[i], rb[i])) << "patch " << i;
  EXPECT_EQ(a.last_stats().vertices, b.last_stats().vertices);
}

TEST(TessCapture, DrawsStayUnderThePointLimit) {
  TESSREF_REQUIRE_GL(ctx);
  const std::vector<TessLevels> many(100, uniform_levels(64.0f));
  TessCapture capture(*ctx);
  capture.capture(TessLayout{}, many);
  const std::size_t per_patch = domain_point_bound(TessLayout{}, many[0]);
  EXPECT_EQ(per_patch, 65u * 65u);
  EXPECT_EQ(capture.last_stats().draws, (100 + 60000 / per_patch - 1) / (60000 / per_patch));
}

TEST(DrawSplit, KeepsOrderAndLimits) {
  EXPECT_TRUE(split_draws({}).empty());
  const std::vector<std::size_t> b = {4225, 0, 30000, 30000, 70000, 1, 1, 1};
  const auto r = split_draws(b, 60000, 3);
  std::vector<std::pair<std::size_t, std::size_t>> got;
  for (const DrawRange& d : r) got.emplace_back(d.first, d.count);
  // {4225, 0, 30000}: 34,225; 30000 alone (+70000 too many); 70000 alone (over the limit, own draw);
  // then three patches, capped by max_patches.
  EXPECT_EQ(got, (std::vector<std::pair<std::size_t, std::size_t>>{{0, 3}, {3, 1}, {4, 1}, {5, 3}}));
}

TEST(TessBounds, DiscardAndClamp) {
  const TessLayout tri;
  TessLevels l = uniform_levels(1.0f);
  EXPECT_EQ(domain_point_bound(tri, l), 9u);  // m = 2
  l.outer[1] = kNaN;
  EXPECT_EQ(domain_point_bound(tri, l), 0u);
  l = uniform_levels(kInf);
  EXPECT_EQ(domain_point_bound(tri, l), 65u * 65u);
  l = uniform_levels(2.0f);
  l.inner[0] = kNaN;
  EXPECT_EQ(domain_point_bound(tri, l), 65u * 65u);
  TessLayout iso;
  iso.domain = TessDomain::Isolines;
  l = uniform_levels(3.0f);
  l.outer[2] = -1.0f;  // not an isoline level
  EXPECT_EQ(domain_point_bound(iso, l), 25u);
  EXPECT_EQ(emitted_vertex_bound(iso, l), 50u);
}

}  // namespace
}  // namespace tessref::glref
