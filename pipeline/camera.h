#pragma once
// The scene's matrices, GL conventions: right-handed world, the camera looking down -z in eye
// space, clip-space depth in [-w, w].
#include <glm/glm.hpp>

#include "pipeline/scene.h"

namespace tessref {

glm::mat4 model_matrix(const Transform& t);  // translate * Rz * Ry * Rx * scale
glm::mat4 view_matrix(const Camera& c);
glm::mat4 projection_matrix(const Camera& c, int width, int height);

}  // namespace tessref
