#version 450 core
// storage_lift.tese writing into its storage block: each invocation stores its height in lift[0],
// which the patches after it read back.
layout(quads, equal_spacing, ccw) in;
in vec3 c_position[];
out vec3 e_normal;
uniform mat4 u_view_proj;
// Each patch lifted by its own amount: a header, then one float per patch, read with length().
layout(std430, binding = 1) buffer Lift {
  vec4 scale;
  float lift[];
};

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
  p.y += scale.x * lift[gl_PrimitiveID % lift.length()] + scale.y * float(lift.length());
  lift[0] = p.y;
  gl_Position = u_view_proj * vec4(p, 1.0);
}
