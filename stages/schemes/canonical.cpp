#include "stages/schemes/canonical.h"

#include <bit>
#include <cstdint>

namespace tessref {

bool corner_less(const glm::vec3& pa, const glm::vec3& na, const glm::vec3& pb,
                 const glm::vec3& nb) {
  for (int i = 0; i < 6; ++i) {
    const auto x = std::bit_cast<std::uint32_t>(i < 3 ? pa[i] : na[i - 3]);
    const auto y = std::bit_cast<std::uint32_t>(i < 3 ? pb[i] : nb[i - 3]);
    if (x != y) return x < y;
  }
  return false;
}

std::array<int, 3> canonical_corner_order(const std::array<glm::vec3, 3>& p,
                                          const std::array<glm::vec3, 3>& n) {
  std::array<int, 3> o{0, 1, 2};
  auto less = [&](int a, int b) { return corner_less(p[a], n[a], p[b], n[b]); };
  // Three-element insertion sort: stable, so equal corners keep index order.
  if (less(o[1], o[0])) std::swap(o[0], o[1]);
  if (less(o[2], o[1])) std::swap(o[1], o[2]);
  if (less(o[1], o[0])) std::swap(o[0], o[1]);
  return o;
}

}  // namespace tessref
