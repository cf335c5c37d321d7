#version 450
// Shades each triangle by the facet normal its geometry shader computed (glsl/facet_normal.geom).
layout(location = 0) in vec3 g_world_position;
layout(location = 1) flat in vec3 g_facet_normal;

layout(location = 0) out vec4 out_color;

void main() {
  float diffuse = max(dot(g_facet_normal, normalize(vec3(-0.3, 0.8, -0.5))), 0.0);
  out_color = vec4(vec3(0.12) + diffuse * vec3(0.9, 0.75, 0.45), 1.0);
}
