#version 450
// Twin of normals.cpp: the normalized interpolated world normal as a color.

layout(location = 0) in vec3 v_world_position;
layout(location = 1) in vec3 v_world_normal;

layout(location = 0) out vec4 out_color;
layout(location = 1) out vec4 out_normal;

void main() {
  vec3 n = normalize(v_world_normal);
  out_color = vec4(n * 0.5 + 0.5, 1.0);
  out_normal = vec4(n, 1.0);
}
