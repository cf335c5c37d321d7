#version 450 core
// Hands each triangle on unchanged: drawing with it gives the bytes drawing without it gives.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in vec3 e_normal[];
out vec3 e_normal_out;

void main() {
  for (int i = 0; i < 3; ++i) {
    gl_Position = gl_in[i].gl_Position;
    e_normal_out = e_normal[i];
    EmitVertex();
  }
}
