#version 450 core
// Takes points: a draw of triangles cannot use it (GL_INVALID_OPERATION).
layout(points) in;
layout(points, max_vertices = 1) out;

void main() {
  gl_Position = gl_in[0].gl_Position;
  EmitVertex();
}
