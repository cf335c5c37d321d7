#pragma once
// Pass-through control program and flat (barycentric) evaluation program.
// GLSL twins: flat.tesc, flat.tese (same directory).
#include "stages/tess_levels_adaptive.h"
#include "stages/tess_stage.h"

namespace tessref {

// layout(vertices = N): gl_out[i] = gl_in[i] for every input vertex slot, levels from settings
// (adaptive levels use the first three vertices' positions). N is usually GL_PATCH_VERTICES; if N
// exceeds the input count, the extra outputs repeat the last input vertex (GL leaves reading
// gl_in past gl_PatchVerticesIn undefined). The GLSL twin copies the vertex shader's two outputs
// (attr[0], attr[1]), all that transform.vert writes.
struct PassThroughTcs : TessControlProgram {
  int vertices = 3;
  TessLevelSettings levels;

  int output_vertices() const override { return vertices; }
  void run(int phase, int invocation_id, const Patch& in, PatchOutput& out) const override;
};

// Triangles: position and normal interpolated from gl_in[0..2] with gl_TessCoord (u, v, w)
// weighting gl_in[0], gl_in[1], gl_in[2]; the normal is renormalized (zero if degenerate).
// Quads: bilinear over gl_in[0..3], (1-u)(1-v) P0 + u(1-v) P1 + u v P2 + (1-u) v P3.
// Isolines: linear from gl_in[0] (u = 0) to gl_in[1] (u = 1).
// Shared edges match bit for bit: on an edge only two terms are non-zero, and a + b == b + a;
// triangle sums also run in the canonical corner order, which keeps signed zeros alike.
struct FlatTes : TessEvalProgram {
  TessLayout tess_layout;
  glm::mat4 view_proj{1.0f};

  TessLayout layout() const override { return tess_layout; }
  ClipVertex evaluate(const glm::vec3& tess_coord, const PatchOutput& patch,
                      int primitive_id) const override;
};

// Fills the varying convention (world position, world normal) and gl_Position = view_proj * p.
ClipVertex make_clip_vertex(const glm::mat4& view_proj, const glm::vec3& position,
                            const glm::vec3& normal);

}  // namespace tessref
