#version 450 core
// Hands each triangle on with the clip and cull distances the evaluation shader wrote: they reach
// the rasterizer through gl_in[].gl_ClipDistance and gl_in[].gl_CullDistance.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in vec3 e_normal[];
out vec3 e_normal_out;
out float gl_ClipDistance[2];
out float gl_CullDistance[1];

void main() {
  for (int i = 0; i < 3; ++i) {
    gl_Position = gl_in[i].gl_Position;
    gl_ClipDistance[0] = gl_in[i].gl_ClipDistance[0];
    gl_ClipDistance[1] = gl_in[i].gl_ClipDistance[1];
    gl_CullDistance[0] = gl_in[i].gl_CullDistance[0];
    e_normal_out = e_normal[i];
    EmitVertex();
  }
}
