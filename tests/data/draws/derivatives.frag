#version 450 core
// Derivatives of the interpolated normal (plain, coarse and fine) and of gl_HelperInvocation: at a
// triangle's edge, a quad's uncovered lanes are helper invocations whose inputs GL interpolates at
// their own pixel, so red and green stay smooth there; blue marks the pixels whose row or column
// of their quad holds a helper.
in vec3 e_normal;
layout(location = 0) out vec4 frag_color;

void main() {
  vec3 dx = dFdx(e_normal), dy = dFdy(e_normal);
  float red = 8.0 * (abs(dx.x) + abs(dy.y));
  float green = 8.0 * (abs(dFdxCoarse(e_normal).z) + abs(dFdyFine(e_normal).z));
  float helper = gl_HelperInvocation ? 1.0 : 0.0;
  frag_color = vec4(clamp(red, 0.0, 1.0), clamp(green, 0.0, 1.0), fwidth(helper), 1.0);
}
