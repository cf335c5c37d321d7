#version 450 core
// Two vertex streams: each triangle's corners as points on stream 0 (drawn, and recorded into
// buffer 0), and one point a triangle on stream 1 (recorded into buffer 1, never drawn) holding
// its first corner's gl_TessCoord and gl_PrimitiveIDIn.
layout(triangles) in;
layout(points, max_vertices = 4) out;
in vec3 f_coord[];
layout(stream = 0) out vec3 g_coord;
layout(stream = 1) out vec4 g_first;

void main() {
  for (int i = 0; i < 3; ++i) {
    gl_Position = gl_in[i].gl_Position;
    g_coord = f_coord[i];
    EmitStreamVertex(0);
  }
  g_first = vec4(f_coord[0], float(gl_PrimitiveIDIn));
  EmitStreamVertex(1);
}
