#version 450 core
// The interpolated normal as a colour.
in vec3 e_normal;
layout(location = 0) out vec4 frag_color;

void main() {
  frag_color = vec4(0.5 * normalize(e_normal) + 0.5, 1.0);
}
