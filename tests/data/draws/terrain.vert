#version 450 core
// Ground corners pass through: the TES displaces the surface.
layout(location = 0) in vec3 in_position;
out vec3 v_position;

void main() {
  v_position = in_position;
}
