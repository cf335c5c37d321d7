#version 450
// Twin of phong.cpp: Phong shading and reflection as in seed 000, Figure 14. Keep the two
// semantically identical (same operations, same order). One-sided; specular not gated by N.L.

layout(location = 0) in vec3 v_world_position;
layout(location = 1) in vec3 v_world_normal;

const int kMaxLights = 8;
uniform vec3 u_eye;
uniform int u_num_lights;
uniform vec3 u_light_position[kMaxLights];
uniform vec3 u_light_intensity[kMaxLights];
uniform float u_ka;
uniform float u_kd;
uniform float u_ks;
uniform float u_shininess;
uniform vec3 u_color;

layout(location = 0) out vec4 out_color;
layout(location = 1) out vec4 out_normal;

void main() {
  vec3 n = normalize(v_world_normal);
  vec3 view = normalize(u_eye - v_world_position);
  vec3 c = vec3(0.0);
  for (int i = 0; i < u_num_lights; ++i) {
    vec3 l = normalize(u_light_position[i] - v_world_position);
    vec3 r = reflect(-l, n);
    c += u_ka * u_light_intensity[i] * u_color +
         u_kd * u_light_intensity[i] * max(dot(n, l), 0.0) * u_color +
         u_ks * u_light_intensity[i] * pow(max(dot(r, view), 0.0), u_shininess);
  }
  out_color = vec4(c, 1.0);
  out_normal = vec4(n, 1.0);
}
