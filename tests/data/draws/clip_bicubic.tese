#version 450 core
// bicubic.tese with user clip planes: gl_ClipDistance[0] cuts along a slanted plane, [1] along
// z = 0.6 (both enabled by the scene), and gl_CullDistance[0] drops every triangle whose three
// corners lie above y = 0.9 (no enable needed), which leaves a jagged edge.
layout(quads, equal_spacing, ccw) in;
in vec3 c_position[];
out vec3 e_normal;
out float gl_ClipDistance[2];
out float gl_CullDistance[1];
uniform mat4 u_view_proj;

void bernstein(float t, out vec4 b, out vec4 d) {
  float s = 1.0 - t;
  b = vec4(s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t);
  d = vec4(-3.0 * s * s, 3.0 * s * s - 6.0 * t * s, 6.0 * t * s - 3.0 * t * t, 3.0 * t * t);
}

void main() {
  vec4 bu, du, bv, dv;
  bernstein(gl_TessCoord.x, bu, du);
  bernstein(gl_TessCoord.y, bv, dv);
  vec3 p = vec3(0.0), pu = vec3(0.0), pv = vec3(0.0);
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      vec3 c = c_position[4 * j + i];
      p += (bu[i] * bv[j]) * c;
      pu += (du[i] * bv[j]) * c;
      pv += (bu[i] * dv[j]) * c;
    }
  }
  e_normal = normalize(cross(pu, pv));
  gl_ClipDistance[0] = 4.7 - p.x - 0.5 * p.z;
  gl_ClipDistance[1] = p.z - 0.6;
  gl_CullDistance[0] = 0.9 - p.y;
  gl_Position = u_view_proj * vec4(p, 1.0);
}
