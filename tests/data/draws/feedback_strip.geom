#version 450 core
// Each triangle as a strip of four vertices (corner 0 again at the end): two triangles, the second
// taken in GL's order for an odd strip triangle (GL 4.5, 10.1.8). Transform feedback records both.
layout(triangles) in;
layout(triangle_strip, max_vertices = 4) out;
in vec3 f_coord[];
flat in int f_patch[];
out vec3 g_coord;
flat out int g_corner;

void main() {
  for (int i = 0; i < 4; ++i) {
    gl_Position = gl_in[i % 3].gl_Position;
    g_coord = f_coord[i % 3];
    g_corner = 4 * gl_PrimitiveIDIn + i;
    EmitVertex();
  }
}
