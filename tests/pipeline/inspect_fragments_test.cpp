// inspect --patch's fragments (inspect/inspect_fragments.h): the patch's fragments are the draw's
// (the pixel query at the nearest one names the same patch, triangle and gl_TessCoord), whatever
// the thread count; hidden fragments are told from visible ones.
#include <numeric>

#include <gtest/gtest.h>

#include "inspect/inspect_fragments.h"
#include "inspect/inspect_pixel.h"
#include "test_util.h"

namespace tessref {
namespace {

TEST(InspectFragments, TheNearestFragmentIsWhatThePixelQueryFinds) {
  const test::LoadedScene l = test::load_default_scene({"image.width=256", "image.height=256"});
  const glm::vec3 near(0.2f, 0.3f, 0.5f);
  const PatchFragments one = patch_fragments(l.scene, l.mesh, 70, 253, near, Parallel(1));
  const PatchFragments two = patch_fragments(l.scene, l.mesh, 70, 253, near, Parallel(2));
  ASSERT_GT(one.count, 50u);
  EXPECT_EQ(one.visible, one.count);  // a front patch in the middle of the torus: nothing covers it
  EXPECT_EQ(std::accumulate(one.per_triangle.begin(), one.per_triangle.end(), std::size_t(0)), one.count);
  EXPECT_EQ(two.count, one.count);
  EXPECT_EQ(two.per_triangle, one.per_triangle);
  ASSERT_TRUE(one.nearest && two.nearest);
  EXPECT_EQ(two.nearest->x, one.nearest->x);
  EXPECT_EQ(two.nearest->y, one.nearest->y);
  const PatchFragment& f = *one.nearest;
  EXPECT_GE(f.x, one.min_x);
  EXPECT_LE(f.x, one.max_x);
  const PixelInspectResult p = inspect_pixel(l.scene, l.mesh, f.x, f.y, Parallel(2));
  ASSERT_TRUE(p.winner);
  const PixelFragment& w = p.fragments[*p.winner];
  EXPECT_EQ(w.patch, 70u);
  EXPECT_EQ(w.triangle, f.triangle);
  EXPECT_EQ(w.tess_coord, f.tess_coord);
  EXPECT_EQ(w.frag_coord.z, f.depth);
}

TEST(InspectFragments, HiddenFragmentsAreCountedApart) {
  // Without culling, the torus's far side is drawn and lost to the near side.
  const test::LoadedScene l = test::load_default_scene({"image.width=256", "image.height=256", "cull_back_faces=false"});
  std::size_t hidden = 0, count = 0;
  for (std::size_t patch = 0; patch < 256; patch += 16) {
    const PatchFragments r = patch_fragments(l.scene, l.mesh, patch, 253, std::nullopt, Parallel(2));
    hidden += r.count - r.visible;
    count += r.count;
  }
  EXPECT_GT(count, 0u);
  EXPECT_GT(hidden, 0u);
}

}  // namespace
}  // namespace tessref
