#version 450 core
// Control points pass through: the patch is evaluated in the TES.
layout(location = 0) in vec3 in_position;
out vec3 v_position;

void main() {
  v_position = in_position;
}
