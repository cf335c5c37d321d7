#include "stages/programs/phong.h"

#include <algorithm>
#include <cmath>

#include "common/simd.h"
#include "stages/programs/shading_lanes.h"
#include "stages/programs/specular_pow.h"
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
         u_ks * u_light_intensity[i] * specular_pow(std::max(glm::dot(r, view), 0.0f), u_shininess);
  }

  FragmentOutput out;
  out.color = glm::vec4(c, 1.0f);
  out.aux = glm::vec4(n, 1.0f);
  return out;
}

ShadingLanes shading_lanes(FragmentBatch& b) {
  static_assert(kFragmentLanes == 64, "the shading kernels run on 64 lanes");
  return ShadingLanes{b.lanes(),
                      {b.varyings[kVaryingPosition], b.varyings[kVaryingPosition + 1],
                       b.varyings[kVaryingPosition + 2]},
                      {b.varyings[kVaryingNormal], b.varyings[kVaryingNormal + 1],
                       b.varyings[kVaryingNormal + 2]},
                      {b.color[0], b.color[1], b.color[2], b.color[3]},
                      {b.aux[0], b.aux[1], b.aux[2], b.aux[3]}};
}

void PhongShader::shade_batch(FragmentBatch& batch) const {
  static_assert(kMaxBatchLights == kMaxLights);
  PhongBatchUniforms u{};
  for (int k = 0; k < 3; ++k) {
    u.eye[k] = u_eye[k];
    u.color[k] = u_color[k];
  }
  u.num_lights = std::clamp(u_num_lights, 0, kMaxLights);
  for (int i = 0; i < u.num_lights; ++i)
    for (int k = 0; k < 3; ++k) {
      u.light_position[i][k] = u_light_position[i][k];
      u.light_intensity[i][k] = u_light_intensity[i][k];
    }
  u.ka = u_ka;
  u.kd = u_kd;
  u.ks = u_ks;
  u.shininess = u_shininess;
  const ShadingLanes io = shading_lanes(batch);
  if (simd_path() == SimdPath::Avx2)
    phong_batch_avx2(u, io);
  else
    phong_batch_scalar(u, io);
}

}  // namespace tessref::programs
