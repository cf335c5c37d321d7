#version 450 core
// Facet normals over a tessellated surface: one line per triangle, from its centroid along the
// mean of its corners' normals (an overlay a geometry shader draws over its own surface).
layout(triangles) in;
layout(line_strip, max_vertices = 2) out;
in vec3 e_normal[];
in vec3 e_world[];
out vec3 g_color;
uniform mat4 u_view_proj;
uniform float u_length;

void main() {
  vec3 c = (e_world[0] + e_world[1] + e_world[2]) / 3.0;
  vec3 n = normalize(e_normal[0] + e_normal[1] + e_normal[2]);
  g_color = vec3(1.0, 0.9, 0.2);
  gl_Position = u_view_proj * vec4(c, 1.0);
  EmitVertex();
  g_color = vec3(1.0, 0.3, 0.1);
  gl_Position = u_view_proj * vec4(c + u_length * n, 1.0);
  EmitVertex();
  EndPrimitive();
}
