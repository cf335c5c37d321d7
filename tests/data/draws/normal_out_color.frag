#version 450 core
// The interpolated normal a geometry shader handed on, as a colour.
in vec3 e_normal_out;
layout(location = 0) out vec4 frag_color;

void main() {
  frag_color = vec4(0.5 * normalize(e_normal_out) + 0.5, 1.0);
}
