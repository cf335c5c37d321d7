#include "mesh/camera.h"

#include <algorithm>
#include <cmath>
#include <vector>

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


Camera fitted_camera(const Scene& scene, const Mesh& mesh) {
  Camera c = scene.camera;
  if (!c.fit || mesh.positions.empty()) return c;
  // In double: the sphere of a large mesh must not overflow while it is measured.
  const glm::dmat4 model(model_matrix(scene.transform));
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  std::vector<glm::dvec3> world;
  world.reserve(mesh.positions.size());
  for (const glm::vec3& p : mesh.positions) {
    world.push_back(glm::dvec3(model * glm::dvec4(glm::dvec3(p), 1.0)));
    lo = glm::min(lo, world.back());
    hi = glm::max(hi, world.back());
  }
  const glm::dvec3 centre = 0.5 * (lo + hi);
  double radius = 0.0;
  for (const glm::dvec3& p : world) radius = std::max(radius, glm::length(p - centre));
  radius = std::max(radius * 1.05, 1e-6);  // margin for what tessellation adds beyond the mesh
  const double half_y = glm::radians(double(c.fov_y_deg)) / 2.0;
  const double half_x = std::atan(std::tan(half_y) * double(scene.width) / double(scene.height));
  const double distance = radius / std::sin(std::min(half_x, half_y));
  const glm::dvec3 back = glm::normalize(glm::dvec3(c.eye) - glm::dvec3(c.target));
  c.target = glm::vec3(centre);
  c.eye = glm::vec3(centre + back * distance);
  c.near = float(std::max(distance - radius, distance * 1e-3));
  c.far = float(distance + radius);
  return c;
}

}  // namespace tessref
