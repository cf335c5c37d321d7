#pragma once
// Procedural displacement along the normal (seed 001, Section 4 and Figure 4), on top of any
// built-in evaluation program: each evaluated point P with unit normal N moves to
//     P' = P + a sin(f |P|) N
// and its normal becomes Blinn's perturbed normal of the height h(P) = a sin(f |P|):
//     g = grad h = a f cos(f |P|) P / |P|,   N' = normalize(N - (g - (g . N) N))
// (exact for a flat patch with a constant normal; it leaves out the terms in h times the base
// surface's curvature, which the paper's figure does not need). sin and cos are tessref's own
// (shader/glsl_math.h), so the GLSL twins' block (u_displacement in pn_triangles.tese and
// flat.tese) gives the same bits on the executor. A zero normal stays zero and moves nothing.
#include "stages/tess_stage.h"

namespace tessref {

struct DisplacementSettings {
  bool enabled = false;
  float amplitude = 0.0f;  // a, world units (negative: inwards)
  float frequency = 0.0f;  // f, radians per world unit of |P|; >= 0
};

// The displaced point and normal (what DisplacedTes writes); p, n: the base program's outputs.
void displace(const DisplacementSettings& d, glm::vec3& p, glm::vec3& n);

// Wraps a built-in TES (varying convention of tess_stage.h): runs it, then displaces its world
// position and normal and recomputes gl_Position = view_proj * P'. `base` must outlive this.
struct DisplacedTes : TessEvalProgram {
  const TessEvalProgram* base = nullptr;
  DisplacementSettings displacement;
  glm::mat4 view_proj{1.0f};

  TessLayout layout() const override { return base->layout(); }
  int num_varyings() const override { return base->num_varyings(); }
  VaryingMask flat_varyings() const override { return base->flat_varyings(); }
  ClipVertex evaluate(const glm::vec3& tess_coord, const PatchOutput& patch,
                      int primitive_id) const override;
  // The base program's batch (its SIMD kernel where it has one), then the same per-point
  // displacement as evaluate(): the same bits.
  void evaluate_batch(const PatchOutput& patch, int primitive_id,
                      TessEvalBatch& batch) const override;
};

}  // namespace tessref
