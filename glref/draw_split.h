#pragma once
// Splitting a run of patches into draws that Mesa llvmpipe renders correctly: its draw module
// keeps TES vertex indices in 16 bits, and a draw generating more than 65,535 domain points gives
// wrong geometry with no error (measured: 20 level-64 triangle patches, 63,380 points, are fine;
// 21, 66,549 points, are not). Every multi-patch draw in glref goes through here.
#include <cstddef>
#include <vector>

namespace tessref::glref {

// Well below 65,535, and below Mesa's internal chunking of large draws.
constexpr std::size_t kSafePointsPerDraw = 60000;

// Mesa's draw module also cuts a draw's index list into chunks of 1,023 indices (341 triangle
// patches) and restarts gl_PrimitiveID at 0 in each: the spider at level 3 (1,312 patches, few
// points each) came back with patch 341 tagged 0. A draw of at most this many patches is one chunk.
constexpr std::size_t max_patches_per_draw(int patch_vertices) {
  return patch_vertices > 0 && patch_vertices < 1023 ? std::size_t(1023 / patch_vertices) : 1;
}

struct DrawRange {
  std::size_t first = 0;  // first patch (glDrawArrays `first` in patches; pass it as the id base)
  std::size_t count = 0;  // patches in this draw
};

// Consecutive ranges covering every patch in order; each range's summed bound stays at or below
// max_points (a single patch over the limit gets a draw of its own) and holds at most
// max_patches patches. point_bounds[i]: an upper bound on patch i's domain points (0 = discarded).
// A renderer whose TCS computes the levels can bound every patch by (64 + 1)^2 = 4,225.
std::vector<DrawRange> split_draws(const std::vector<std::size_t>& point_bounds,
                                   std::size_t max_points = kSafePointsPerDraw,
                                   std::size_t max_patches = 16384);

}  // namespace tessref::glref
