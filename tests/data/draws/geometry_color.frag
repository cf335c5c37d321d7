#version 450 core
in vec3 g_color;
layout(location = 0) out vec4 frag_color;

void main() {
  frag_color = vec4(g_color, 1.0);
}
