// llvmpipe's fill rule, as stated in common/fixed_point.h: top-left in memory rows, so with GL's
// y up centers on a bottom edge (horizontal, interior above) or a left edge are inside, on a top
// or right edge outside. The same pixel sets come out of llvmpipe (raster_vs_llvmpipe_test).
#include <set>
#include <utility>

#include <gtest/gtest.h>

#include "raster_test_util.h"

namespace tessref {
namespace {

constexpr int kW = 16, kH = 16;
using PixelSet = std::set<std::pair<int, int>>;

PixelSet covered(const TriangleBatch& batch) {
  Framebuffer fb(kW, kH);
  test::CountingProgram counter(kW, kH);
  draw_triangles(batch, RasterState{}, counter, fb, Parallel(1));
  PixelSet s;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      EXPECT_LE(counter.at(x, y), 1u);
      if (counter.at(x, y)) s.insert({x, y});
    }
  return s;
}

TriangleBatch triangle(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
  TriangleBatch t;
  test::add_triangle(t, test::window_vertex(a.x, a.y, 0.5f, kW, kH),
                     test::window_vertex(b.x, b.y, 0.5f, kW, kH),
                     test::window_vertex(c.x, c.y, 0.5f, kW, kH));
  return t;
}

// The square of pixel centers [2.5, 10.5] x [2.5, 10.5], cut along the diagonal y = x.
const glm::vec2 kBottomLeft(2.5f, 2.5f), kTopLeft(2.5f, 10.5f), kTopRight(10.5f, 10.5f),
    kBottomRight(10.5f, 2.5f);

TEST(RasterFillRule, LeftEdgeInsideTopEdgeOutside) {
  // Upper-left half: a left edge x = 2.5 (inside), a top edge y = 10.5 (outside), the diagonal
  // on its lower right (a right edge: outside).
  PixelSet expected;
  for (int x = 2; x <= 8; ++x)
    for (int y = x + 1; y <= 9; ++y) expected.insert({x, y});
  EXPECT_EQ(expected.size(), 28u);
  EXPECT_EQ(covered(triangle(kTopLeft, kBottomLeft, kTopRight)), expected);
  // Winding does not change coverage.
  EXPECT_EQ(covered(triangle(kTopLeft, kTopRight, kBottomLeft)), expected);
  EXPECT_FALSE(expected.count({2, 10}));  // the top-left corner pixel: on the top edge
  EXPECT_TRUE(expected.count({2, 9}));
}

TEST(RasterFillRule, BottomEdgeInsideRightEdgeOutside) {
  // Lower-right half: a bottom edge y = 2.5 (inside), a right edge x = 10.5 (outside), the
  // diagonal on its upper left (a left edge: inside).
  PixelSet expected;
  for (int x = 2; x <= 9; ++x)
    for (int y = 2; y <= x; ++y) expected.insert({x, y});
  EXPECT_EQ(expected.size(), 36u);
  EXPECT_EQ(covered(triangle(kBottomLeft, kBottomRight, kTopRight)), expected);
  EXPECT_EQ(covered(triangle(kBottomLeft, kTopRight, kBottomRight)), expected);
  EXPECT_TRUE(expected.count({2, 2}));    // the bottom-left corner: on the bottom and diagonal
  EXPECT_FALSE(expected.count({10, 2}));  // the bottom-right corner: on the right edge
}

TEST(RasterFillRule, DiagonalSplitSquareCoversEachPixelOnce) {
  TriangleBatch both = triangle(kTopLeft, kBottomLeft, kTopRight);
  TriangleBatch lower = triangle(kBottomLeft, kBottomRight, kTopRight);
  both.vertices.insert(both.vertices.end(), lower.vertices.begin(), lower.vertices.end());
  test::make_depth_decreasing(both);
  PixelSet expected;  // left and bottom sides in, right and top out
  for (int x = 2; x <= 9; ++x)
    for (int y = 2; y <= 9; ++y) expected.insert({x, y});
  EXPECT_EQ(covered(both), expected);  // covered() also checks no pixel is hit twice

  // The other diagonal, from top-left to bottom-right.
  TriangleBatch other = triangle(kTopLeft, kBottomLeft, kBottomRight);
  TriangleBatch upper = triangle(kTopLeft, kBottomRight, kTopRight);
  other.vertices.insert(other.vertices.end(), upper.vertices.begin(), upper.vertices.end());
  test::make_depth_decreasing(other);
  EXPECT_EQ(covered(other), expected);
}

TEST(RasterFillRule, SlopedEdgesThroughPixelCenters) {
  // Left edge x = 2.5 + (y - 2.5) / 2 through centers (3.5, 4.5), (4.5, 6.5), (5.5, 8.5): inside.
  // Right edge x = 12.5 - 3/4 (y - 2.5) through the center (9.5, 6.5): outside.
  const PixelSet s = covered(triangle({2.5f, 2.5f}, {12.5f, 2.5f}, {6.5f, 10.5f}));
  EXPECT_TRUE(s.count({3, 4}) && s.count({4, 6}) && s.count({5, 8}));
  EXPECT_FALSE(s.count({9, 6}));
  EXPECT_TRUE(s.count({8, 6}) && s.count({10, 4}));  // just inside the right edge
  EXPECT_TRUE(s.count({5, 2}) && s.count({11, 2}));  // bottom edge: inside
  EXPECT_TRUE(s.count({2, 2}));    // the bottom-left vertex is on the left and the bottom edge
  EXPECT_FALSE(s.count({12, 2}));  // the bottom-right vertex is on the right edge
  EXPECT_FALSE(s.count({6, 10}));  // the apex is on the left and the right edge: outside
  // Row by row, centers x + 0.5 in [left, right): the spans worked out by hand.
  const int spans[][3] = {{2, 2, 11}, {3, 3, 11}, {4, 3, 10}, {5, 4, 9},
                          {6, 4, 8},  {7, 5, 8},  {8, 5, 7},  {9, 6, 6}};
  PixelSet expected;
  for (const auto& r : spans)
    for (int x = r[1]; x <= r[2]; ++x) expected.insert({x, r[0]});
  EXPECT_EQ(expected.size(), 46u);
  EXPECT_EQ(s, expected);
}

TEST(RasterFillRule, ZeroAreaTrianglesAreDropped) {
  TriangleBatch b = triangle({1.5f, 1.5f}, {5.5f, 5.5f}, {9.5f, 9.5f});  // collinear
  TriangleBatch pt = triangle({4.5f, 4.5f}, {4.5f, 4.5f}, {4.5f, 4.5f});
  b.vertices.insert(b.vertices.end(), pt.vertices.begin(), pt.vertices.end());
  Framebuffer fb(kW, kH);
  test::CountingProgram counter(kW, kH);
  RasterStats s = draw_triangles(b, RasterState{}, counter, fb, Parallel(1));
  EXPECT_EQ(s.triangles_in, 2u);
  EXPECT_EQ(s.triangles_culled, 2u);
  EXPECT_EQ(s.triangles_rasterized, 0u);
  EXPECT_EQ(s.fragments_shaded, 0u);
}

TEST(RasterFillRule, BackFaceCullingAndFrontFacing) {
  const TriangleBatch ccw = triangle(kBottomLeft, kBottomRight, kTopRight);
  const TriangleBatch cw = triangle(kBottomLeft, kTopRight, kBottomRight);
  test::VaryingProgram prog;
  for (bool cull : {false, true}) {
    RasterState state;
    state.cull_back_faces = cull;
    Framebuffer fb(kW, kH);
    RasterStats s = draw_triangles(ccw, state, prog, fb, Parallel(1));
    EXPECT_EQ(s.fragments_shaded, 36u);
    EXPECT_EQ(fb.aux[fb.index(5, 4)].y, 1.0f);  // front facing
    Framebuffer fb2(kW, kH);
    s = draw_triangles(cw, state, prog, fb2, Parallel(1));
    EXPECT_EQ(s.fragments_shaded, cull ? 0u : 36u);
    EXPECT_EQ(s.triangles_culled, cull ? 1u : 0u);
    if (!cull) {
      EXPECT_EQ(fb2.aux[fb2.index(5, 4)].y, 0.0f);  // back facing
    }
  }
}

}  // namespace
}  // namespace tessref
