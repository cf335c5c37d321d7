// gl_FragDepth: a fragment program that writes depth is tested after shading with what it wrote,
// clamped to [0, 1], and stored in the buffer's format.
#include <gtest/gtest.h>

#include "raster_test_util.h"

namespace tessref {
namespace {

constexpr int kW = 32, kH = 32;

// Writes varying 0 as gl_FragDepth and varying 1 as the red channel.
struct DepthWriter : FragmentProgram {
  FragmentOutput shade(const FragmentInput&) const override { return {}; }
  bool writes_depth() const override { return true; }
  void shade_batch(FragmentBatch& batch) const override {
    for (int l = 0; l < batch.lanes(); ++l) {
      batch.frag_depth[l] = batch.varyings[0][l];
      for (int c = 0; c < 4; ++c) batch.color[c][l] = c == 0 ? batch.varyings[1][l] : 1.0f;
    }
  }
};

// A full-viewport rectangle at clip z (window depth (z + 1) / 2) carrying (depth, red).
TriangleBatch rectangle(float z, float depth, float red) {
  TriangleBatch b;
  b.num_varyings = 2;
  auto v = [&](float x, float y) {
    ClipVertex c;
    c.position = glm::vec4(x, y, z, 1.0f);
    c.varyings[0] = depth;
    c.varyings[1] = red;
    return c;
  };
  test::add_triangle(b, v(-1, -1), v(1, -1), v(1, 1));
  test::add_triangle(b, v(-1, -1), v(1, 1), v(-1, 1));
  return b;
}

TEST(FragDepth, TheWrittenDepthIsTestedAndStored) {
  const DepthWriter prog;
  RasterState state;  // GL_LESS, depth writes on
  for (const DepthFormat format : {DepthFormat::k32F, DepthFormat::k24}) {
    Framebuffer fb(kW, kH);
    fb.depth_format = format;
    // Interpolated depth 0.25, written 0.5: 0.5 is stored.
    draw_triangles(rectangle(-0.5f, 0.5f, 0.1f), state, prog, fb, Parallel(2));
    EXPECT_EQ(fb.depth[0], stored_depth(format, 0.5f));
    // Interpolated 0.75 (behind 0.5: an early test would drop it), written 0.375: passes.
    draw_triangles(rectangle(0.5f, 0.375f, 0.2f), state, prog, fb, Parallel(2));
    EXPECT_EQ(fb.depth[0], stored_depth(format, 0.375f));
    EXPECT_EQ(fb.color[0].r, 0.2f);
    // Interpolated 0, written 0.4 (behind 0.375): fails, nothing changes.
    const RasterStats s = draw_triangles(rectangle(-1.0f, 0.4f, 0.3f), state, prog, fb, Parallel(2));
    EXPECT_EQ(s.fragments_depth_failed, std::uint64_t(kW * kH));
    EXPECT_EQ(fb.color[0].r, 0.2f);
    // Written -2 is clamped to 0 (for GL_DEPTH_COMPONENT32F too, as llvmpipe stores it).
    draw_triangles(rectangle(0.0f, -2.0f, 0.4f), state, prog, fb, Parallel(2));
    EXPECT_EQ(fb.depth[0], 0.0f);
    // Written 7 is clamped to 1: with GL_ALWAYS it is stored.
    RasterState always = state;
    always.depth_func = DepthFunc::kAlways;
    draw_triangles(rectangle(0.0f, 7.0f, 0.5f), always, prog, fb, Parallel(2));
    EXPECT_EQ(fb.depth[std::size_t(kW * kH - 1)], 1.0f);
  }
}

}  // namespace
}  // namespace tessref
