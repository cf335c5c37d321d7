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

// Triangles in submission order: the order is part of the result (depth ties resolve to the
// earlier triangle), so producers must fill it deterministically. Indexed (3 indices per triangle
// into `vertices`, each vertex stored and transformed once) or, with no indices, consecutive
// vertex triples. Both forms of the same triangles draw the same bytes.
struct TriangleBatch {
  std::vector<ClipVertex> vertices;
  std::vector<std::uint32_t> indices;  // used when indexed
  bool indexed = false;
  int num_varyings = 0;
  // Bit j set: varying j is flat (not interpolated): every fragment of a triangle gets the value
  // of its provoking vertex, the last one (GL_LAST_VERTEX_CONVENTION).
  std::uint32_t flat_varyings = 0;
  std::size_t triangle_count() const { return (indexed ? indices.size() : vertices.size()) / 3; }
  std::size_t vertex_index(std::size_t triangle, int corner) const {
    const std::size_t k = 3 * triangle + std::size_t(corner);
    return indexed ? indices[k] : k;
  }
  const ClipVertex& corner(std::size_t triangle, int corner) const {
    return vertices[vertex_index(triangle, corner)];
  }
  void clear() {
    vertices.clear();
    indices.clear();
  }
};

// The same triangles as consecutive triples (for tools and tests that walk corners in order).
TriangleBatch expand_indices(const TriangleBatch& batch);
// Appends src's triangles to dst (indexed if either is).
void append_triangles(TriangleBatch& dst, const TriangleBatch& src);

}  // namespace tessref
