#include "stages/schemes/displacement.h"

#include <cmath>

#include "shader/glsl_math.h"
#include "stages/schemes/canonical.h"
#include "stages/schemes/flat.h"

namespace tessref {

// Operation for operation the twins' displace() (pn_triangles.tese, flat.tese).
void displace(const DisplacementSettings& d, glm::vec3& p, glm::vec3& n) {
  if (n == glm::vec3(0.0f)) return;
  const float a = d.amplitude, f = d.frequency;
  const float r = std::sqrt(glm::dot(p, p));
  const float s = shader::math::sin(f * r), c = shader::math::cos(f * r);
  // The gradient of |P| is P / |P|; at the origin it has none.
  const glm::vec3 g = r > 0.0f ? p * (a * f * c / r) : glm::vec3(0.0f);
  const glm::vec3 tangential = g - n * glm::dot(g, n);
  p = canonical_zero(p + n * (a * s));
  n = canonical_zero(safe_normalize(n - tangential));
}

ClipVertex DisplacedTes::evaluate(const glm::vec3& tc, const PatchOutput& patch,
                                  int primitive_id) const {
  ClipVertex v = base->evaluate(tc, patch, primitive_id);
  glm::vec3 p, n;
  for (int c = 0; c < 3; ++c) {
    p[c] = v.varyings[kVaryingPosition + c];
    n[c] = v.varyings[kVaryingNormal + c];
  }
  displace(displacement, p, n);
  const ClipVertex moved = make_clip_vertex(view_proj, p, n);
  v.position = moved.position;
  for (int c = 0; c < 3; ++c) {
    v.varyings[kVaryingPosition + c] = p[c];
    v.varyings[kVaryingNormal + c] = n[c];
  }
  return v;
}

void DisplacedTes::evaluate_batch(const PatchOutput& patch, int primitive_id,
                                  TessEvalBatch& batch) const {
  base->evaluate_batch(patch, primitive_id, batch);
  for (int i = 0; i < batch.count; ++i) {
    glm::vec3 p, n;
    for (int c = 0; c < 3; ++c) {
      p[c] = batch.varyings[kVaryingPosition + c][i];
      n[c] = batch.varyings[kVaryingNormal + c][i];
    }
    displace(displacement, p, n);
    const ClipVertex moved = make_clip_vertex(view_proj, p, n);
    for (int c = 0; c < 4; ++c) batch.position[c][i] = moved.position[c];
    for (int c = 0; c < 3; ++c) {
      batch.varyings[kVaryingPosition + c][i] = p[c];
      batch.varyings[kVaryingNormal + c][i] = n[c];
    }
  }
}

}  // namespace tessref
