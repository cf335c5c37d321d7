#version 450 core
// The interpolated colour.
in vec3 e_color;
layout(location = 0) out vec4 frag_color;

void main() {
  frag_color = vec4(e_color, 1.0);
}
