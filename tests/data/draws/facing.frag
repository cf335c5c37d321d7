#version 450 core
// Green on front faces, red on back faces.
layout(location = 0) out vec4 frag_color;

void main() {
  frag_color = gl_FrontFacing ? vec4(0.1, 0.9, 0.2, 1.0) : vec4(0.9, 0.1, 0.1, 1.0);
}
