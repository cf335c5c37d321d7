#version 450 core
// Terrain: the ground point raised by a mip-mapped height map. An evaluation shader has no
// derivatives, so the level is explicit: textureLod at u_height_lod, between two mip levels.
layout(quads, fractional_odd_spacing, ccw) in;
in vec3 c_position[];
out vec2 e_uv;
out vec3 e_normal;
out vec4 e_light;  // the point in the light's clip space, for the shadow lookup
uniform mat4 u_view_proj;
uniform mat4 u_light_view_proj;
uniform bool u_light_pass;  // the shadow map's pass: seen from the light
uniform sampler2D u_height;
uniform float u_size;        // the ground spans [0, u_size] in x and z
uniform float u_scale;       // the height of a texel value of 1
uniform float u_height_lod;  // textureLod's level of detail

float height_at(vec2 uv) {
  return textureLod(u_height, uv, u_height_lod).r * u_scale;
}

void main() {
  const vec3 p0 = mix(c_position[0], c_position[1], gl_TessCoord.x);
  const vec3 p1 = mix(c_position[3], c_position[2], gl_TessCoord.x);
  vec3 p = mix(p0, p1, gl_TessCoord.y);
  const vec2 uv = p.xz / u_size;
  const float e = 1.0 / 64.0;
  const float hx = height_at(uv + vec2(e, 0.0)) - height_at(uv - vec2(e, 0.0));
  const float hz = height_at(uv + vec2(0.0, e)) - height_at(uv - vec2(0.0, e));
  p.y += height_at(uv);
  e_uv = uv;
  e_normal = normalize(vec3(-hx, 2.0 * e * u_size, -hz));
  e_light = u_light_view_proj * vec4(p, 1.0);
  gl_Position = u_light_pass ? e_light : u_view_proj * vec4(p, 1.0);
}
