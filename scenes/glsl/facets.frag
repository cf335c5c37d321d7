#version 450
// Facet shading from screen-space derivatives: the normal of each triangle's plane, from dFdx and
// dFdy of the world position, with no normal varying (a common way to show a mesh's facets). At a
// triangle's edge the derivatives need the quad's helper invocations.
layout(location = 0) in vec3 v_world_position;

layout(location = 0) out vec4 out_color;

void main() {
  vec3 n = normalize(cross(dFdx(v_world_position), dFdy(v_world_position)));
  float diffuse = max(dot(n, normalize(vec3(-0.3, 0.8, -0.5))), 0.0);
  out_color = vec4(vec3(0.12) + diffuse * vec3(0.9, 0.75, 0.45), 1.0);
}
