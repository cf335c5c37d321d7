#version 450 core
// Each quad bulges by its entry of the std140 block's float array (stride 16 bytes).
layout(quads, equal_spacing, ccw) in;
in vec3 c_position[];
in vec4 c_color[];
out vec3 e_normal;
out vec4 e_color;
uniform mat4 u_view_proj;
layout(std140, binding = 1) uniform Shading {
  vec3 light_dir;
  float ambient;
  mat3 tint_matrix;
  float bulge[3];
  vec2 spare;
};

void main() {
  const vec2 t = gl_TessCoord.xy;
  const vec3 p0 = mix(c_position[0], c_position[1], t.x);
  const vec3 p1 = mix(c_position[3], c_position[2], t.x);
  vec3 p = mix(p0, p1, t.y);
  const float h = bulge[gl_PrimitiveID % 3];
  const float shape = 16.0 * t.x * (1.0 - t.x) * t.y * (1.0 - t.y);
  p.y += h * shape;
  // d(shape)/du and d/dv scaled by the patch's size (1 here): the normal of the bump.
  const float du = 16.0 * (1.0 - 2.0 * t.x) * t.y * (1.0 - t.y);
  const float dv = 16.0 * t.x * (1.0 - t.x) * (1.0 - 2.0 * t.y);
  e_normal = normalize(vec3(-h * du, 1.0, -h * dv));
  e_color = mix(mix(c_color[0], c_color[1], t.x), mix(c_color[3], c_color[2], t.x), t.y);
  gl_Position = u_view_proj * vec4(p, 1.0);
}
