#pragma once
// The plain structs the geometry stages hand to the rasterizer.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace tessref {

// Varyings carried from the last geometry stage to the fragment shader. A fixed size keeps vertex
// batches plain arrays; slots past TriangleBatch::num_varyings are ignored.
inline constexpr int kMaxVaryings = 12;

struct ClipVertex {
  glm::vec4 position{0.0f};                  // gl_Position, clip space
  std::array<float, kMaxVaryings> varyings{};  // interpolated perspective-correctly
};

// Triangles as consecutive vertex triples, in submission order: the order is part of the result
// (depth ties resolve to the earlier triangle), so producers must fill it deterministically.
struct TriangleBatch {
  std::vector<ClipVertex> vertices;
  int num_varyings = 0;
  std::size_t triangle_count() const { return vertices.size() / 3; }
};

}  // namespace tessref
