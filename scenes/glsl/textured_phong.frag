#version 450
// phong.frag with one light (a constant count, as an application compiles it) and its colour
// from a mip-mapped texture: the torus's angle around its axis and around its tube as (s, t),
// sampled with implicit LOD (scenes/textured.json, the textured-frame benchmark). The angles are
// taken in world space, around the y axis, which the scene's 20-degree tilt leaves close enough.
layout(location = 0) in vec3 v_world_position;
layout(location = 1) in vec3 v_world_normal;

uniform vec3 u_eye;
uniform vec3 u_light_position[8];
uniform vec3 u_light_intensity[8];
uniform float u_ka;
uniform float u_kd;
uniform float u_ks;
uniform float u_shininess;
uniform sampler2D u_albedo;

layout(location = 0) out vec4 out_color;
layout(location = 1) out vec4 out_normal;

void main() {
  vec3 p = v_world_position;
  float around = atan(p.z, p.x);                    // the torus's axis is y
  float tube = atan(p.y, length(p.xz) - 1.0);       // major radius 1
  vec2 uv = vec2(around, tube) * (2.0 / 6.28318531);
  vec3 albedo = texture(u_albedo, uv).rgb;
  vec3 n = normalize(v_world_normal);
  vec3 view = normalize(u_eye - v_world_position);
  vec3 l = normalize(u_light_position[0] - v_world_position);
  vec3 r = reflect(-l, n);
  vec3 c = u_ka * u_light_intensity[0] * albedo + u_kd * u_light_intensity[0] * max(dot(n, l), 0.0) * albedo +
           u_ks * u_light_intensity[0] * pow(max(dot(r, view), 0.0), u_shininess);
  out_color = vec4(c, 1.0);
  out_normal = vec4(n, 1.0);
}
