#include <gtest/gtest.h>

#include "raster/rasterizer.h"

namespace tessref {
namespace {

struct ConstantColor : FragmentProgram {
  FragmentOutput shade(const FragmentInput& in) const override {
    FragmentOutput o;
    o.color = glm::vec4(1.0f);
    return o;
  }
};

TEST(RasterSmoke, FullScreenQuadCoversEveryPixelOnce) {
  TriangleBatch batch;
  auto v = [](float x, float y) { ClipVertex c; c.position = glm::vec4(x, y, 0.0f, 1.0f); return c; };
  batch.vertices = {v(-1, -1), v(1, -1), v(1, 1), v(-1, -1), v(1, 1), v(-1, 1)};
  Framebuffer fb(100, 70);
  RasterStats s = draw_triangles(batch, RasterState{}, ConstantColor{}, fb, Parallel(1));
  EXPECT_EQ(s.triangles_in, 2u);
  EXPECT_EQ(s.triangles_rasterized, 2u);
  EXPECT_EQ(s.fragments_shaded, 7000u);
  for (float d : fb.depth) ASSERT_EQ(d, 0.5f);
}

}  // namespace
}  // namespace tessref
