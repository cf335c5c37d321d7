#version 450 core
// The ground's patch corners pass through: the evaluation shader displaces the surface.
layout(location = 0) in vec3 in_position;
out vec3 v_position;

void main() {
  v_position = in_position;
}
