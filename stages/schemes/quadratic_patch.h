#pragma once
// Quadratic Bézier triangles as a TCS/TES pair: what Phong tessellation, NLSA and Nagata triangles
// have in common (seed 004 Sec. 2: the three differ in their mid-edge control points only).
// The control programs of the schemes (phong.h, nlsa.h, nagata.h) derive from QuadraticTcs and
// supply the edge rule; they share QuadraticTes. GLSL twins: phong.tesc, nlsa.tesc, nagata.tesc
// and quadratic_patch.tese (same directory). Formulas: bezier_nets.h.
//
// Corner mapping as in pn_triangles.h: gl_in[0], [1], [2] weighted by gl_TessCoord.x, .y, .z are
// the papers' p0, p1, p2. With (a, b, c) = gl_TessCoord,
//   s = p0 a^2 + p1 b^2 + p2 c^2 + 2 b110 a b + 2 b011 b c + 2 b101 a c.
#include "stages/schemes/pn_triangles.h"
#include "stages/tess_levels_adaptive.h"
#include "stages/tess_stage.h"

namespace tessref {

// Output layout of the quadratic control programs (also what QuadraticTes reads):
//   gl_out[i].attr[0] = P_i (xyz, 1), attr[1] = N_i = safe_normalize(input normal) (xyz, 0),
//   attr[2] = the mid-edge control point of edge (i, (i+1)%3) (xyz, 1),
//   attr[3] = the mid-edge normal coefficient of edge (i, (i+1)%3) (quadratic normal modes; else 0),
//   patch[0] = canonical corner order (canonical.h) as floats.
inline constexpr int kQuadAttrEdgePoint = 2;
inline constexpr int kQuadAttrMidNormal = 3;
inline constexpr int kQuadPatchOrder = 0;

// layout(vertices = 3); phase 0: corners, unit normals, levels (invocation 0); barrier();
// phase 1: each invocation its edge's control point and mid-edge normal, invocation 0 the
// canonical order. The edge rules are symmetric in their ends bit for bit (bezier_nets.h), so
// both patches of a shared edge get the same control point.
struct QuadraticTcs : TessControlProgram {
  // The normal field the TES evaluates: every normal mode applies to every scheme (seed 004
  // Sec. 4 shows linear, quadratic and analytic normals on all four); the quadratic ones need the
  // mid-edge normals written here.
  PnNormalMode normal_mode = PnNormalMode::Quadratic;
  TessLevelSettings levels;

  int output_vertices() const override { return 3; }
  int phases() const override { return 2; }
  void run(int phase, int invocation_id, const Patch& in, PatchOutput& out) const override;

  // The scheme's mid-edge control point (b110 for p0, p1) from the edge's points and unit normals.
  virtual glm::vec3 edge_point(const glm::vec3& p0, const glm::vec3& n0, const glm::vec3& p1,
                               const glm::vec3& n1) const = 0;
};

// Evaluates the quadratic patch and the normal field, the terms summed in the canonical corner
// order: shared edges give bit-identical positions (all modes) and normals (all but analytic,
// whose normal depends on the cross-edge derivative). Analytic: normalize(d/dt1 x d/dt2),
// oriented to agree with the linear normal; a zero cross product falls back to the linear normal.
struct QuadraticTes : TessEvalProgram {
  PnNormalMode normal_mode = PnNormalMode::Quadratic;
  TessSpacing spacing = TessSpacing::FractionalOdd;
  TessWinding winding = TessWinding::Ccw;
  bool point_mode = false;
  glm::mat4 view_proj{1.0f};

  TessLayout layout() const override {
    return TessLayout{TessDomain::Triangles, spacing, winding, point_mode};
  }
  ClipVertex evaluate(const glm::vec3& tess_coord, const PatchOutput& patch,
                      int primitive_id) const override;
  // Reads the patch once, then evaluates each point as evaluate() does (same bits).
  void evaluate_batch(const PatchOutput& patch, int primitive_id,
                      TessEvalBatch& batch) const override;
};

// The pieces of QuadraticTes, for tests and tools. tc is gl_TessCoord.
glm::vec3 quadratic_position(const PatchOutput& patch, const glm::vec3& tc);
glm::vec3 quadratic_normal(const PatchOutput& patch, const glm::vec3& tc, PnNormalMode mode);
// d/dt1 moves weight from gl_in[0] to gl_in[1], d/dt2 from gl_in[0] to gl_in[2], as pn_derivatives.
void quadratic_derivatives(const PatchOutput& patch, const glm::vec3& tc, glm::vec3& d_t1,
                           glm::vec3& d_t2);

}  // namespace tessref
