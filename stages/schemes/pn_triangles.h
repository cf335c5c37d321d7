#pragma once
// Curved PN triangles (Vlachos et al. 2001) as a TCS/TES pair, with four normal fields.
// GLSL twins: pn_triangles.tesc, pn_triangles.tese (same directory). Formulas: shared notes
// formulas.md (the seed papers' typos are not followed).
//
// Corner mapping: the paper's P1, P2, P3 with weights (w, u, v) are gl_in[0], gl_in[1], gl_in[2],
// weighted by gl_TessCoord.x, .y, .z respectively (GL 4.6 section 11.2.2.1).
#include <string>

#include "stages/tess_levels_adaptive.h"
#include "stages/tess_stage.h"

namespace tessref {

enum class PnNormalMode {
  Linear,              // normalize(sum of weight_i N_i)
  Quadratic,           // Vlachos: n110 = normalize(N1 + N2 - v12 (P2 - P1)), v12 = 2 d.(N1+N2)/d.d
  QuadraticCorrected,  // 001 App. A: n110 = N1 + N2 - t12 (P2 - P1), t12 = 4 d.(N1+N2)/d.d, unnormalized
  Analytic,            // normalize(db/du x db/dv), oriented to agree with the linear normal
};
const char* to_string(PnNormalMode m);
bool parse(const std::string& s, PnNormalMode& out);  // "linear" | "quadratic" | "quadratic_corrected" | "analytic"

// Output layout of the PN control program (also what the TES reads):
//   gl_out[i].attr[0] = P_i (xyz, 1), attr[1] = N_i = safe_normalize(input normal) (xyz, 0),
//   attr[2] = tangent coefficient next to P_i towards P_(i+1)%3, attr[3] = towards P_(i+2)%3,
//   attr[4] = mid-edge normal coefficient of edge (i, (i+1)%3) (quadratic modes; else 0)
//   patch[0] = b111, patch[1] = canonical corner order (see canonical.h) as floats.
inline constexpr int kPnAttrTangentNext = 2;
inline constexpr int kPnAttrTangentPrev = 3;
inline constexpr int kPnAttrMidNormal = 4;
inline constexpr int kPnPatchCenter = 0;
inline constexpr int kPnPatchOrder = 1;

// layout(vertices = 3); phase 0: corners, normals, tangent coefficients, levels (invocation 0);
// barrier(); phase 1: mid-edge normals (each invocation its edge) and b111 + order (invocation 0).
// Degenerate data does not produce NaN: a zero normal stays zero, a zero-length edge gets no
// normal correction (v_ij = 0).
struct PnTcs : TessControlProgram {
  PnNormalMode normal_mode = PnNormalMode::Quadratic;
  TessLevelSettings levels;

  int output_vertices() const override { return 3; }
  int phases() const override { return 2; }
  void run(int phase, int invocation_id, const Patch& in, PatchOutput& out) const override;
};

// Evaluates the cubic patch and the chosen normal field. Position, linear and quadratic normals
// sum their terms in the canonical corner order, so shared edges give bit-identical positions
// (all modes) and normals (all but analytic, whose normal depends on the cross-edge derivative).
// Analytic: a zero cross product (degenerate tangents) falls back to the linear normal.
struct PnTes : TessEvalProgram {
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
  // Linear and quadratic normal fields run the SIMD kernel of pn_batch.h (same bits as
  // evaluate()); the analytic field runs evaluate() per point.
  void evaluate_batch(const PatchOutput& patch, int primitive_id,
                      TessEvalBatch& batch) const override;
};

// The pieces of PnTes::evaluate, for tests and tools. tc is gl_TessCoord.
glm::vec3 pn_position(const PatchOutput& patch, const glm::vec3& tc);
glm::vec3 pn_normal(const PatchOutput& patch, const glm::vec3& tc, PnNormalMode mode);
// Derivatives of the position along the domain: d/dt1 moves weight from gl_in[0] to gl_in[1],
// d/dt2 from gl_in[0] to gl_in[2] (tc.x = 1 - t1 - t2). Their cross product follows the corner
// order gl_in[0] -> [1] -> [2] (right-handed).
void pn_derivatives(const PatchOutput& patch, const glm::vec3& tc, glm::vec3& d_t1, glm::vec3& d_t2);

}  // namespace tessref
