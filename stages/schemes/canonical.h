#pragma once
// A canonical order of a triangle's corners, from their data alone, so that a point on an edge
// shared by two patches is computed by the same float operations, in the same order, in both:
// a shared edge then tessellates to bit-identical vertices whatever the corner order of each patch.
#include <array>

#include <glm/glm.hpp>

namespace tessref {

// The order itself: lexicographic on the bit patterns of (position, normal).
bool corner_less(const glm::vec3& pa, const glm::vec3& na, const glm::vec3& pb,
                 const glm::vec3& nb);

// Orders corners by the bit patterns of (position, normal), lexicographically (a total order, NaN
// included); ties keep index order. Returns the corner indices, first to last.
std::array<int, 3> canonical_corner_order(const std::array<glm::vec3, 3>& positions,
                                          const std::array<glm::vec3, 3>& normals);

// After a canonical sum, -0 and +0 may differ between two patches (zero terms carry signs);
// adding +0 turns -0 into +0 and leaves everything else as it is.
inline glm::vec3 canonical_zero(const glm::vec3& v) { return v + glm::vec3(0.0f); }

}  // namespace tessref
