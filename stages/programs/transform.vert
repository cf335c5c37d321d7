#version 450
// Twin of transform.cpp: keep the two semantically identical (same operations, same order).

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;

uniform mat4 u_model;
uniform mat4 u_view_projection;
uniform mat3 u_normal_matrix;  // inverse transpose of mat3(u_model), computed on the CPU

layout(location = 0) out vec3 v_world_position;
layout(location = 1) out vec3 v_world_normal;

void main() {
  vec4 world = u_model * vec4(in_position, 1.0);
  gl_Position = u_view_projection * world;
  v_world_position = world.xyz;
  v_world_normal = u_normal_matrix * in_normal;
}
