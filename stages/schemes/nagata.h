#pragma once
// Nagata triangles (Nagata 2005) as a control program over the quadratic patch
// (quadratic_patch.h): each edge is the quadratic whose end tangents are orthogonal to the end
// normals, b110 = (p0 + p1)/2 - c1/2, with seed 004's threshold eps against near-parallel normals
// (Sec. 2.3; bezier_nets.h: nagata_curvature). GLSL twin: nagata.tesc (evaluation:
// quadratic_patch.tese).
#include "stages/schemes/bezier_nets.h"
#include "stages/schemes/quadratic_patch.h"

namespace tessref {

struct NagataTcs : QuadraticTcs {
  float eps = float(schemes::kDefaultNagataEps);  // c1 = 0 when dc <= eps or 1 - dc <= eps

  glm::vec3 edge_point(const glm::vec3& p0, const glm::vec3& n0, const glm::vec3& p1,
                       const glm::vec3& n1) const override;
};

}  // namespace tessref
