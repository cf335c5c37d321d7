#include "stages/programs/phong.h"

#include <cmath>

#include "stages/tess_stage.h"

namespace tessref::programs {

FragmentOutput PhongShader::shade(const FragmentInput& in) const {
  const float* v = in.varyings;
  glm::vec3 v_world_position(v[kVaryingPosition], v[kVaryingPosition + 1],
                             v[kVaryingPosition + 2]);
  glm::vec3 v_world_normal(v[kVaryingNormal], v[kVaryingNormal + 1],
                           v[kVaryingNormal + 2]);

  glm::vec3 n = glm::normalize(v_world_normal);
  glm::vec3 view = glm::normalize(u_eye - v_world_position);
  glm::vec3 c(0.0f);
  for (int i = 0; i < u_num_lights; ++i) {
    glm::vec3 l = glm::normalize(u_light_position[i] - v_world_position);
    glm::vec3 r = glm::reflect(-l, n);
    c += u_ka * u_light_intensity[i] * u_color +
         u_kd * u_light_intensity[i] * std::max(glm::dot(n, l), 0.0f) * u_color +
         u_ks * u_light_intensity[i] * std::pow(std::max(glm::dot(r, view), 0.0f), u_shininess);
  }

  FragmentOutput out;
  out.color = glm::vec4(c, 1.0f);
  out.aux = glm::vec4(n, 1.0f);
  return out;
}

}  // namespace tessref::programs
