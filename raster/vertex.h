#pragma once
// The plain structs the geometry stages hand to the rasterizer.
#include <array>
#include <bitset>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace tessref {

// Varyings carried from the last geometry stage to the fragment shader: GL 4.5's minimum
// MAX_FRAGMENT_INPUT_COMPONENTS.
inline constexpr int kMaxVaryings = 128;

// A vertex is stored as one or more 64-byte records, so that the common case (the built-in
// programs: at most 12 varyings) stays one cache line per vertex: the first record holds
// gl_Position and varyings 0..11, each further record 16 more. A vertex's floats are contiguous:
// position, then its num_varyings varyings (TriangleBatch::vertex_data).
inline constexpr int kRecordVaryings = 12;
struct ClipVertex {
  glm::vec4 position{0.0f};                     // gl_Position, clip space
  std::array<float, kRecordVaryings> varyings{};  // interpolated perspective-correctly
};
static_assert(sizeof(ClipVertex) == 16 * sizeof(float));

// Records per vertex for num_varyings varyings.
constexpr int vertex_records(int num_varyings) {
  return num_varyings <= kRecordVaryings ? 1 : 1 + (num_varyings - kRecordVaryings + 15) / 16;
}

// Bit j: varying j is flat.
using VaryingMask = std::bitset<kMaxVaryings>;

// Primitives of `Corners` vertices (3 triangles, 2 lines, 1 points) in submission order: the
// order is part of the result (depth ties resolve to the earlier primitive), so producers must fill
// it deterministically. Indexed (Corners indices per primitive into `vertices`, each vertex stored
// and transformed once) or, with no indices, consecutive vertex groups. Both forms of the same
// primitives draw the same bytes.
template <int Corners>
struct PrimitiveBatch {
  static constexpr int kCorners = Corners;
  std::vector<ClipVertex> vertices;  // records(): vertex v starts at vertices[v * records()]
  std::vector<std::uint32_t> indices;  // used when indexed
  bool indexed = false;
  int num_varyings = 0;
  // Bit j set: varying j is flat (not interpolated): every fragment of a primitive gets the value
  // of its provoking vertex, the last one (GL_LAST_VERTEX_CONVENTION).
  VaryingMask flat_varyings;
  int records() const { return vertex_records(num_varyings); }
  std::size_t vertex_count() const { return vertices.size() / std::size_t(records()); }
  // Vertex v's floats: gl_Position (4), then its varyings.
  const float* vertex_data(std::size_t v) const {
    return reinterpret_cast<const float*>(vertices.data() + v * std::size_t(records()));
  }
  std::size_t primitive_count() const {
    return (indexed ? indices.size() : vertex_count()) / std::size_t(Corners);
  }
  std::size_t triangle_count() const requires(Corners == 3) { return primitive_count(); }
  std::size_t vertex_index(std::size_t primitive, int corner) const {
    const std::size_t k = std::size_t(Corners) * primitive + std::size_t(corner);
    return indexed ? indices[k] : k;
  }
  // A corner's first record (its varyings continue in the following records).
  const ClipVertex& corner(std::size_t primitive, int corner) const {
    return vertices[vertex_index(primitive, corner) * std::size_t(records())];
  }
  void clear() {
    vertices.clear();
    indices.clear();
  }
};
using TriangleBatch = PrimitiveBatch<3>;
using LineBatch = PrimitiveBatch<2>;   // GL_LINES: each line's own two vertices
using PointBatch = PrimitiveBatch<1>;

// The same triangles as consecutive triples (for tools and tests that walk corners in order).
TriangleBatch expand_indices(const TriangleBatch& batch);
// Appends src's primitives to dst (indexed if either is); both carry src.num_varyings varyings.
template <int Corners>
void append_primitives(PrimitiveBatch<Corners>& dst, const PrimitiveBatch<Corners>& src);
inline void append_triangles(TriangleBatch& dst, const TriangleBatch& src) { append_primitives(dst, src); }

}  // namespace tessref
