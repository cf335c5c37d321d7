#version 450
// A geometry shader after the tessellation stages: each generated triangle gets the normal of its
// own plane, from its three world positions, handed to the fragment shader flat (the classic use
// of a geometry shader for faceted shading).
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

layout(location = 0) in vec3 v_world_position[];
layout(location = 1) in vec3 v_world_normal[];

layout(location = 0) out vec3 g_world_position;
layout(location = 1) flat out vec3 g_facet_normal;

void main() {
  vec3 n = normalize(cross(v_world_position[1] - v_world_position[0], v_world_position[2] - v_world_position[0]));
  for (int i = 0; i < 3; ++i) {
    gl_Position = gl_in[i].gl_Position;
    g_world_position = v_world_position[i];
    g_facet_normal = n;
    EmitVertex();
  }
  EndPrimitive();
}
