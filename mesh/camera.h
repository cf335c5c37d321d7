#pragma once
// The scene's matrices, GL conventions: right-handed world, the camera looking down -z in eye
// space, clip-space depth in [-w, w].
#include <glm/glm.hpp>

#include "mesh/mesh.h"
#include "scene/scene.h"

namespace tessref {

glm::mat4 model_matrix(const Transform& t);  // translate * Rz * Ry * Rx * scale
glm::mat4 view_matrix(const Camera& c);
glm::mat4 projection_matrix(const Camera& c, int width, int height);

// camera.fit: the camera moved along its view direction (eye - target) until the bounding sphere
// of the transformed mesh fills the narrower field of view with a 5% margin; target = the sphere's
// centre, near and far enclosing the sphere. Returns `scene.camera` unchanged when fit is off.
Camera fitted_camera(const Scene& scene, const Mesh& mesh);

}  // namespace tessref
