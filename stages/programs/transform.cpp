#include "stages/programs/transform.h"

namespace tessref::programs {

TransformVertexShader TransformVertexShader::from(const glm::mat4& model,
                                                  const glm::mat4& view_projection) {
  return {model, view_projection, glm::transpose(glm::inverse(glm::mat3(model)))};
}

VertexOut TransformVertexShader::main(const glm::vec3& in_position,
                                      const glm::vec3& in_normal) const {
  glm::vec4 world = u_model * glm::vec4(in_position, 1.0f);
  VertexOut out;
  out.gl_Position = u_view_projection * world;
  out.v_world_position = glm::vec3(world);
  out.v_world_normal = u_normal_matrix * in_normal;
  return out;
}

}  // namespace tessref::programs
