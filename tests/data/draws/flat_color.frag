#version 450 core
// One colour for the whole draw.
uniform vec4 u_fill;
layout(location = 0) out vec4 frag_color;

void main() {
  frag_color = u_fill;
}
