#version 450 core
// Terrain: the ground point moved up by the height map, sampled at level 0 (a TES has no
// derivatives, so textureLod), its normal from the height map's differences.
layout(quads, equal_spacing, ccw) in;
in vec3 c_position[];
out vec3 e_normal;
out float e_height;
uniform mat4 u_view_proj;
uniform sampler2D u_height;
uniform float u_size;    // the ground spans [0, u_size] in x and z
uniform float u_scale;   // height of a texel value of 1

float height_at(vec2 uv) {
  return textureLod(u_height, uv, 0.0).r * u_scale;
}

void main() {
  const vec3 p0 = mix(c_position[0], c_position[1], gl_TessCoord.x);
  const vec3 p1 = mix(c_position[3], c_position[2], gl_TessCoord.x);
  vec3 p = mix(p0, p1, gl_TessCoord.y);
  const vec2 uv = p.xz / u_size;
  const float h = height_at(uv);
  const float e = 1.0 / 32.0;
  const float hx = height_at(uv + vec2(e, 0.0)) - height_at(uv - vec2(e, 0.0));
  const float hz = height_at(uv + vec2(0.0, e)) - height_at(uv - vec2(0.0, e));
  p.y += h;
  e_normal = normalize(vec3(-hx, 2.0 * e * u_size, -hz));
  e_height = h / u_scale;
  gl_Position = u_view_proj * vec4(p, 1.0);
}
