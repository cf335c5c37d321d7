// Summaries of samples: the sample standard deviation, and Table 3's spread about half the mean.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "stats/summary.h"
#include "stats/surface_stats.h"

namespace tessref::stats {
namespace {

TEST(Summary, SampleStandardDeviation) {
  const std::vector<double> x = {1.0, 2.0, 3.0, 4.0};
  const Summary s = summarize(x);
  EXPECT_EQ(s.count, 4u);
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_DOUBLE_EQ(s.std_dev, std::sqrt(5.0 / 3.0));  // 1/(n-1), as seed 004 defines it
  EXPECT_EQ(s.min, 1.0);
  EXPECT_EQ(s.max, 4.0);
  // sqrt(s^2 + (mean/2)^2)
  EXPECT_DOUBLE_EQ(s.seed004_table3_spread(), std::sqrt(5.0 / 3.0 + 1.5625));
}

TEST(Summary, EmptyAndSingle) {
  EXPECT_EQ(summarize(std::vector<double>{}).count, 0u);
  const Summary one = summarize(std::vector<double>{7.0});
  EXPECT_EQ(one.mean, 7.0);
  EXPECT_EQ(one.std_dev, 0.0);
}

TEST(TriangleGrid, Seed004Densities) {
  EXPECT_EQ(triangle_grid(kSeed004Segments, false).size(), 231u);  // Table 3
  EXPECT_EQ(triangle_grid(kSeed004Segments, true).size(), 171u);   // Table 5
  for (const glm::dvec2& p : triangle_grid(20, true)) {
    EXPECT_GT(p.x, 0.0);
    EXPECT_GT(p.y, 0.0);
    EXPECT_LT(p.x + p.y, 1.0);
  }
  EXPECT_THROW(triangle_grid(2, true), std::invalid_argument);
}

}  // namespace
}  // namespace tessref::stats
