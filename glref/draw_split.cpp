#include "glref/draw_split.h"

#include <algorithm>

namespace tessref::glref {

std::vector<DrawRange> split_draws(const std::vector<std::size_t>& point_bounds, std::size_t max_points,
                                   std::size_t max_patches) {
  max_patches = std::max<std::size_t>(max_patches, 1);
  std::vector<DrawRange> out;
  std::size_t first = 0;
  while (first < point_bounds.size()) {
    std::size_t end = first, points = 0;
    while (end < point_bounds.size() && end - first < max_patches) {
      const std::size_t p = point_bounds[end];
      if (end > first && points + p > max_points) break;
      points += p;
      ++end;
    }
    out.push_back({first, end - first});
    first = end;
  }
  return out;
}

}  // namespace tessref::glref
