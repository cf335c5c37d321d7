#pragma once
// Phong tessellation (Boubekeur & Alexa 2008) as a control program over the quadratic patch
// (quadratic_patch.h): in Bézier form (seed 004 Eq. 2) the mid-edge point is the edge midpoint
// moved by alpha towards the average of the corners projected into each other's tangent planes.
// GLSL twin: phong.tesc (evaluation: quadratic_patch.tese).
#include "stages/schemes/quadratic_patch.h"

namespace tessref {

struct PhongTcs : QuadraticTcs {
  float alpha = 0.75f;  // shape factor: 0 the flat triangle, 3/4 the paper's choice

  glm::vec3 edge_point(const glm::vec3& p0, const glm::vec3& n0, const glm::vec3& p1,
                       const glm::vec3& n1) const override;
};

}  // namespace tessref
