#pragma once
// Scalar Tagged PN triangles (seed 001, Appendix B; Boubekeur, Reuter & Schlick's ST-meshes):
// PN triangles whose tangent coefficients and corner normals follow per-vertex tags.
// GLSL twin: scalar_tagged_pn.tesc (same directory) with pn_triangles.tese; the vertex stage
// passes the tags on (stages/programs/tagged_transform.vert). docs/scalar-tagged-pn.md has the
// formulas, the choices where the appendix is silent, and the sidecar file.
//
// Tags of vertex j: tension theta_j, sharpness sigma_j, bias beta_j, crease vector Delta_j (zero on
// smooth vertices). With N_j the unit normal and P_j the position, for the tangent coefficient
// next to V_j on the edge towards V_k:
//     d   = P_j + (1 - theta_j) / 3 (P_k - P_j)
//     b   = d + Pi(P_j, X, d) X                   (the edge {j, k} is not a crease edge)
//     b   = d + Pi(P_j, N_j, d) Y_j               (it is: both ends carry a crease vector)
//     Pi(p, n, q) = -n . (q - p),   X = normalize((1 - sigma_j) N_j + N'),  Y_j = normalize(N_j + beta_j Delta_j)
//     N'  = normalize(N_j + s sigma_j Delta_j),  s = +1 where Delta_j . (P_k - P_j) >= 0, else -1
// The side s is the edge's (both patches of an edge agree on it: no crack). The corner normal the
// patch shades with is N' for the triangle's side, s = sign of Delta_j . (P_k + P_l - 2 P_j).
// A corner with theta = 0, no sharpness and no crease edge keeps PN's coefficient, computed as
// PnTcs does: with every tag neutral the net is PnTcs's bit for bit.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "stages/schemes/pn_triangles.h"

namespace tessref {

// The TCS's gl_in[] slots beyond position and normal (the vertex stage's outputs 2 and 3).
inline constexpr int kAttrTags = 2;    // (tension, sharpness, bias, 0)
inline constexpr int kAttrCrease = 3;  // (crease vector in world space, 0)
// Output slot beside PN's layout (pn_triangles.h): the smooth unit normal N_j. The canonical
// corner order is taken from it, not from the per-side normal in attr[1], so that the two patches
// of a crease edge evaluate it with the same operations.
inline constexpr int kStpnAttrSmoothNormal = 5;

struct VertexTags {
  float tension = 0.0f;    // theta, in [-1, 1]; 0: PN
  float sharpness = 0.0f;  // sigma, in [0, 1]; > 0 only with a crease vector
  float bias = 0.0f;       // beta, in [-1, 1]; != 0 only with a crease vector
  glm::vec3 crease{0.0f};  // Delta; zero: a smooth vertex
  bool creased() const { return crease != glm::vec3(0.0f); }
};

// Layout (vertices = 3), two phases, the PN net of PnTcs with the tagged coefficients and normals
// (PnTes evaluates it). Runs PnTcs and then replaces what the tags change.
struct ScalarTaggedPnTcs : TessControlProgram {
  PnTcs pn;  // normal_mode and levels live here

  int output_vertices() const override { return 3; }
  int phases() const override { return 2; }
  void run(int phase, int invocation_id, const Patch& in, PatchOutput& out) const override;
};

// The crease vector as the vertex stage hands it on: turned by the normal matrix, its length kept
// (so that sharpness and bias weigh it against the unit normal whatever the model's scale).
glm::vec3 world_crease(const glm::mat3& normal_matrix, const glm::vec3& crease);

}  // namespace tessref
