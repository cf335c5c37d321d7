// tessref's primitive generator against Mesa llvmpipe, live: for every domain, spacing, winding
// and point mode, 2,000 level sets (random non-integer levels and the boundary values) must give
// the identical gl_TessCoord stream: same count, same bits, same order.
#include <gtest/gtest.h>

#include <bit>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "gl_fixture.h"
#include "glref/tess_capture.h"
#include "stages/tpg.h"
#include "stages/tpg_stream.h"
#include "../tpg/tpg_test_util.h"

namespace tessref {
namespace {

int level_sets() {
  const char* env = std::getenv("TESSREF_TPG_SETS");  // more for a longer soak
  return env ? std::atoi(env) : 2000;
}

bool same_bits(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (std::bit_cast<std::uint32_t>(a[i][k]) != std::bit_cast<std::uint32_t>(b[i][k]))
        return false;
  return true;
}

using Config = std::tuple<TessDomain, TessSpacing, TessWinding, bool>;
class TpgVsLlvmpipe : public ::testing::TestWithParam<Config> {};

TEST_P(TpgVsLlvmpipe, IdenticalStreams) {
  TESSREF_REQUIRE_GL(ctx);
  const auto [domain, spacing, winding, point_mode] = GetParam();
  const TessLayout layout{domain, spacing, winding, point_mode};
  std::mt19937 rng(2024 + int(domain) * 100 + int(spacing) * 10 + int(winding) * 2 + point_mode);
  std::vector<TessLevels> sets;
  for (int n = 0; n < level_sets(); ++n) sets.push_back(test::random_levels(rng));

  glref::TessCapture capture(*ctx);
  const auto captured = capture.capture(layout, sets);
  ASSERT_EQ(captured.size(), sets.size());
  int matches = 0, first_bad = -1;
  for (std::size_t i = 0; i < sets.size(); ++i) {
    const auto ours = emitted_stream(generate_tessellation(layout, sets[i]));
    if (same_bits(ours, captured[i])) ++matches;
    else if (first_bad < 0) first_bad = int(i);
  }
  std::printf("[ llvmpipe ] %s %s %s%s: %d / %zu level sets identical\n", to_string(domain),
              to_string(spacing), to_string(winding), point_mode ? " point_mode" : "", matches,
              sets.size());
  if (first_bad >= 0) {
    const TessLevels& l = sets[first_bad];
    ADD_FAILURE() << "first mismatch: set " << first_bad << " outer " << l.outer[0] << ","
                  << l.outer[1] << "," << l.outer[2] << "," << l.outer[3] << " inner "
                  << l.inner[0] << "," << l.inner[1];
  }
  EXPECT_EQ(matches, int(sets.size()));
}

INSTANTIATE_TEST_SUITE_P(
    AllLayouts, TpgVsLlvmpipe,
    ::testing::Combine(::testing::Values(TessDomain::Triangles, TessDomain::Quads,
                                         TessDomain::Isolines),
                       ::testing::Values(TessSpacing::Equal, TessSpacing::FractionalOdd,
                                         TessSpacing::FractionalEven),
                       ::testing::Values(TessWinding::Ccw, TessWinding::Cw),
                       ::testing::Bool()),
    [](const auto& info) {
      return std::string(to_string(std::get<0>(info.param))) + "_" +
             to_string(std::get<1>(info.param)) + "_" + to_string(std::get<2>(info.param)) +
             (std::get<3>(info.param) ? "_points" : "");
    });

}  // namespace
}  // namespace tessref
