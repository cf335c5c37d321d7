// The raster section of common/fixed_point.h: 24.8 snapping and the fill-rule predicate.
#include <gtest/gtest.h>

#include <limits>

#include "common/fixed_point.h"

namespace tessref {
namespace {

TEST(RasterFixedPoint, SnapIs24Point8RoundedToNearestEven) {
  EXPECT_EQ(fixed::snap_subpixel(1.0f), 256);
  EXPECT_EQ(fixed::snap_subpixel(0.5f / 256.0f), 0);  // tie to even
  EXPECT_EQ(fixed::snap_subpixel(1.5f / 256.0f), 2);  // tie to even
  EXPECT_EQ(fixed::snap_subpixel(-1.5f / 256.0f), -2);
  // 16383.99f is 16383.990234375; times 256 that is 4194301.5 exactly, a tie: to even.
  EXPECT_EQ(fixed::snap_subpixel(16383.99f), 4194302);
  EXPECT_EQ(fixed::pixel_center(3), 3 * 256 + 128);
}

// fuzz_pipeline: the clipper's float rounding on mesh coordinates near 1e37 gave a window
// coordinate of 4.4e30, whose conversion to int was undefined behaviour. Beyond the clip guard
// band (2^15 pixels) coordinates clamp; NaN takes the low end.
TEST(RasterFixedPoint, SnapClampsCoordinatesClippingCannotProduce) {
  const std::int32_t limit = (1 << (fixed::kGuardBits + 1)) * fixed::kSubpixelOne;
  EXPECT_EQ(fixed::snap_subpixel(4.4335e30f), limit);
  EXPECT_EQ(fixed::snap_subpixel(-1e38f), -limit);
  EXPECT_EQ(fixed::snap_subpixel(std::numeric_limits<float>::infinity()), limit);
  EXPECT_EQ(fixed::snap_subpixel(std::numeric_limits<float>::quiet_NaN()), -limit);
  EXPECT_EQ(fixed::snap_subpixel(32767.5f), 8388480);  // inside: unchanged
}

TEST(RasterFixedPoint, BottomLeftEdgesInWindowCoordinatesForCounterClockwiseTriangles) {
  // llvmpipe's top-left rule in memory rows: bottom-left with GL's y up.
  EXPECT_TRUE(fixed::is_top_left_edge(5, 0));    // bottom: horizontal, running toward +x
  EXPECT_FALSE(fixed::is_top_left_edge(-5, 0));  // top
  EXPECT_TRUE(fixed::is_top_left_edge(3, -4));   // left: running down
  EXPECT_TRUE(fixed::is_top_left_edge(0, -4));
  EXPECT_TRUE(fixed::is_top_left_edge(-3, -4));
  EXPECT_FALSE(fixed::is_top_left_edge(-3, 4));  // right: running up
  EXPECT_FALSE(fixed::is_top_left_edge(0, 4));
  EXPECT_FALSE(fixed::is_top_left_edge(3, 4));
  // An edge and its reverse: exactly one of the two triangles sharing it owns it.
  for (int dx = -3; dx <= 3; ++dx)
    for (int dy = -3; dy <= 3; ++dy)
      if (dx || dy) {
        EXPECT_NE(fixed::is_top_left_edge(dx, dy), fixed::is_top_left_edge(-dx, -dy));
      }
}

}  // namespace
}  // namespace tessref
