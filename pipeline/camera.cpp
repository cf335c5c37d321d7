#include "pipeline/camera.h"

#include <glm/gtc/matrix_transform.hpp>

namespace tessref {

glm::mat4 model_matrix(const Transform& t) {
  glm::mat4 m = glm::translate(glm::mat4(1.0f), t.translate);
  m = glm::rotate(m, glm::radians(t.rotate_deg.z), glm::vec3(0.0f, 0.0f, 1.0f));
  m = glm::rotate(m, glm::radians(t.rotate_deg.y), glm::vec3(0.0f, 1.0f, 0.0f));
  m = glm::rotate(m, glm::radians(t.rotate_deg.x), glm::vec3(1.0f, 0.0f, 0.0f));
  return glm::scale(m, t.scale);
}

glm::mat4 view_matrix(const Camera& c) { return glm::lookAt(c.eye, c.target, c.up); }

glm::mat4 projection_matrix(const Camera& c, int width, int height) {
  return glm::perspective(glm::radians(c.fov_y_deg), float(width) / float(height), c.near, c.far);
}

}  // namespace tessref
