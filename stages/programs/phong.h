#pragma once
// Phong shading and reflection as in seed 000, Figure 14 (GLSL twin: phong.frag):
//   color = sum over lights of  ka * I * color
//                             + kd * I * max(N.L, 0) * color
//                             + ks * I * max(R.V, 0)^shininess      (white specular)
// with N the normalized interpolated world normal, L and V unit vectors to the light and the eye,
// R = reflect(-L, N), and I the light's intensity (I_a = I_d = I_s). One-sided: N is not flipped
// on back faces, and the specular term is not gated by N.L (the caption's formula as written).
#include <array>

#include <glm/glm.hpp>

#include "raster/rasterizer.h"
// Reads the varyings at kVaryingPosition and kVaryingNormal (stages/tess_stage.h).

namespace tessref::programs {

inline constexpr int kMaxLights = 8;  // phong.frag's uniform arrays

struct PhongShader final : FragmentProgram {
  // uniforms
  glm::vec3 u_eye{0.0f};
  int u_num_lights = 0;
  std::array<glm::vec3, kMaxLights> u_light_position{};
  std::array<glm::vec3, kMaxLights> u_light_intensity{};
  float u_ka = 0.0f, u_kd = 0.0f, u_ks = 0.0f, u_shininess = 1.0f;
  glm::vec3 u_color{1.0f};

  // out_color: the shaded color, alpha 1; out_normal (aux): (N, 1).
  FragmentOutput shade(const FragmentInput& in) const override;
  // The SIMD kernel of shading_batch.h: the same bits as shade() per live lane.
  void shade_batch(FragmentBatch& batch) const override;
};

}  // namespace tessref::programs
