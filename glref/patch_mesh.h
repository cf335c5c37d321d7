#pragma once
// A mesh drawn as GL_PATCHES through whatever program is bound (VS -> TCS -> TES -> FS), with the
// draw split so llvmpipe never sees more than kSafePointsPerDraw tessellated vertices at once.
// The start of the scene renderer: attributes at the locations tessref's GLSL twins use.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "glref/draw_split.h"

namespace tessref::glref {

class GlContext;
class Program;

struct PatchMeshData {
  std::vector<glm::vec3> positions;     // attribute location 0
  std::vector<glm::vec3> normals;       // location 1; empty = not supplied (reads as 0,0,0,1)
  std::vector<std::uint32_t> indices;   // patch_vertices per patch
  int patch_vertices = 3;
  // Scalar Tagged PN's tags (tagged_transform.vert): location 2 (tension, sharpness, bias, 0) and
  // location 3 (crease vector); empty = not supplied.
  std::vector<glm::vec4> tags;
  std::vector<glm::vec3> creases;
};

class PatchMesh {
 public:
  // Throws GlError for inconsistent data (index out of range, sizes that do not divide).
  PatchMesh(GlContext& context, const PatchMeshData& data);
  ~PatchMesh();
  PatchMesh(const PatchMesh&) = delete;
  PatchMesh& operator=(const PatchMesh&) = delete;

  std::size_t patch_count() const { return patch_count_; }

  // Draws every patch with `program` into whatever framebuffer is bound. point_bounds: an upper
  // bound on each patch's domain points (domain_point_bound() from known levels); empty = the
  // worst case for GL_MAX_TESS_GEN_LEVEL, (max + 1)^2 per patch. Sets the uniform int
  // u_patch_base, where the program has one, to each draw's first patch (gl_PrimitiveID restarts
  // at 0 with every draw). Returns the number of draws.
  std::size_t draw(const Program& program, const std::vector<std::size_t>& point_bounds = {},
                   std::size_t max_points_per_draw = kSafePointsPerDraw);

  // Draws with rasterizer discard and returns the program's transform-feedback output: the
  // program must be linked with interleaved varyings of 32-bit components (float, int bits),
  // `words_per_vertex` of them per vertex, and its last stage must emit `primitive` (GL_TRIANGLES,
  // GL_LINES or GL_POINTS: the TES output). Patches come back in order, each draw checked for
  // primitives written == generated. To check the llvmpipe trap, capture u_patch_base +
  // gl_PrimitiveID and verify it.
  std::vector<std::uint32_t> capture(const Program& program, int words_per_vertex, unsigned primitive,
                                     const std::vector<std::size_t>& point_bounds = {},
                                     std::size_t max_points_per_draw = kSafePointsPerDraw);

 private:
  GlContext& context_;
  std::vector<std::size_t> bounds_or_worst_case(const std::vector<std::size_t>& point_bounds) const;
  void draw_range(const DrawRange& d, int base_location);

  unsigned vao_ = 0, position_buffer_ = 0, normal_buffer_ = 0, index_buffer_ = 0;
  unsigned feedback_buffer_ = 0, query_generated_ = 0, query_written_ = 0;
  unsigned tags_buffer_ = 0, crease_buffer_ = 0;
  std::size_t feedback_capacity_ = 0;
  std::size_t patch_count_ = 0;
  int patch_vertices_ = 3;
};

}  // namespace tessref::glref
