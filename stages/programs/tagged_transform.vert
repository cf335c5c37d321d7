#version 450
// Twin of transform.cpp with Scalar Tagged PN's per-vertex tags handed on to the control shader
// (pipeline/vertex_tags.cpp attach_vertex_tags, stages/schemes/scalar_tagged_pn.h world_crease).

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec4 in_tags;    // (tension, sharpness, bias, 0)
layout(location = 3) in vec3 in_crease;  // crease vector, model space; zero on smooth vertices

uniform mat4 u_model;
uniform mat4 u_view_projection;
uniform mat3 u_normal_matrix;  // inverse transpose of mat3(u_model), computed on the CPU

layout(location = 0) out vec3 v_world_position;
layout(location = 1) out vec3 v_world_normal;
layout(location = 2) out vec4 v_tags;
layout(location = 3) out vec3 v_crease;

vec3 safe_normalize(vec3 v) {
  float len2 = dot(v, v);
  if (!(len2 > 0.0) || isinf(len2) || isnan(len2)) return vec3(0.0);
  return v / sqrt(len2);
}

void main() {
  vec4 world = u_model * vec4(in_position, 1.0);
  gl_Position = u_view_projection * world;
  v_world_position = world.xyz;
  v_world_normal = u_normal_matrix * in_normal;
  v_tags = in_tags;
  // Turned like a normal, its length kept: sharpness and bias weigh it against the unit normal.
  float len = sqrt(dot(in_crease, in_crease));
  v_crease = safe_normalize(u_normal_matrix * in_crease) * len;
}
