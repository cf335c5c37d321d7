#pragma once
// NLSA triangles (Barrera et al. 2002, near least square acceleration) as a control program over
// the quadratic patch (quadratic_patch.h): each edge curve averages the two least-squares
// quadratics that match one end's tangent exactly, with tangents from the normals by
// Gram-Schmidt (seed 004 Sec. 2.4). The same surface as Phong tessellation with alpha = 1/2, built
// the paper's way. GLSL twin: nlsa.tesc (evaluation: quadratic_patch.tese).
#include "stages/schemes/quadratic_patch.h"

namespace tessref {

struct NlsaTcs : QuadraticTcs {
  glm::vec3 edge_point(const glm::vec3& p0, const glm::vec3& n0, const glm::vec3& p1,
                       const glm::vec3& n1) const override;
};

}  // namespace tessref
