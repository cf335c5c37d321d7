#pragma once
// A triangle mesh as the draw call consumes it: one shared position and unit normal per vertex,
// counter-clockwise triangles (seen from outside), so that PN tessellation sees watertight edges.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tessref {

struct Mesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  // one per position, unit length
  std::vector<std::uint32_t> indices;  // 3 per triangle
  std::size_t vertex_count() const { return positions.size(); }
  std::size_t triangle_count() const { return indices.size() / 3; }
};

// What validate_mesh repaired (callers print these as warnings).
struct MeshRepairs {
  std::size_t degenerate_triangles_dropped = 0;
  std::size_t normals_recomputed = 0;  // zero-length or non-finite normals replaced from faces
};

// Checks a mesh at the boundary of the program and repairs what can be repaired:
//   errors (InputError "<source>: ..."): no triangles, index count not a multiple of 3,
//     non-finite positions, indices out of range, a normal count different from the position count,
//     no triangle left after dropping degenerate ones, a bad normal at a vertex no face can fix;
//   repairs: degenerate triangles (repeated index or zero area) are dropped, zero-length or
//     non-finite normals are recomputed from the faces, all normals are normalized.
MeshRepairs validate_mesh(Mesh& mesh, const std::string& source);

// A normal welding keeps (then normalizes): finite and not (nearly) zero. Others are replaced.
bool usable_normal(const glm::vec3& n);

// Angle-weighted average of the unit face normals around each vertex; where every angle at a
// vertex rounds to zero (a needle's tip), the area-weighted average; zero where no
// non-degenerate face touches the vertex. Summed in triangle order: deterministic.
std::vector<glm::vec3> face_weighted_normals(const std::vector<glm::vec3>& positions,
                                             const std::vector<std::uint32_t>& indices);

// Merges vertices with bit-identical positions (first occurrence keeps its place), so that each
// position carries one shared normal. With input normals, the welded normal is the normalized sum
// of the normals merged into it; without them (or where that sum is zero) it comes from the faces.
Mesh weld_by_position(const std::vector<glm::vec3>& positions,
                      const std::vector<glm::vec3>& normals,  // empty or one per position
                      const std::vector<std::uint32_t>& indices);

}  // namespace tessref
