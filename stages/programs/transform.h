#pragma once
// The vertex shader (GLSL twin: transform.vert): object space to world and clip space.
#include <glm/glm.hpp>

namespace tessref::programs {

// The vertex shader's outputs. Without tessellation they become a ClipVertex (varyings at
// kVaryingPosition and kVaryingNormal of stages/tess_stage.h); with it, the TCS's input
// (StageVertex attributes kAttrPosition and kAttrNormal).
struct VertexOut {
  glm::vec4 gl_Position{0.0f};
  glm::vec3 v_world_position{0.0f};
  glm::vec3 v_world_normal{0.0f};  // not normalized
};

struct TransformVertexShader {
  // uniforms
  glm::mat4 u_model{1.0f};
  glm::mat4 u_view_projection{1.0f};
  glm::mat3 u_normal_matrix{1.0f};  // inverse transpose of mat3(u_model)

  static TransformVertexShader from(const glm::mat4& model, const glm::mat4& view_projection);

  VertexOut main(const glm::vec3& in_position, const glm::vec3& in_normal) const;
};

}  // namespace tessref::programs
