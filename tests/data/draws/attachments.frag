#version 450 core
// One output per draw buffer: the normal as a colour; the same at alpha 0.4 (blended into an
// sRGB attachment); the normal scaled past 8 bits' range (kept by a half-float attachment, rounded
// by its format); the window coordinates.
in vec3 e_normal;
layout(location = 0) out vec4 out_color;
layout(location = 1) out vec4 out_blended;
layout(location = 2) out vec4 out_scaled;
layout(location = 3) out vec4 out_coord;

void main() {
  vec3 n = normalize(e_normal);
  out_color = vec4(0.5 * n + 0.5, 1.0);
  out_blended = vec4(0.5 * n + 0.5, 0.4);
  out_scaled = vec4(n * (1000.0 / 3.0), 1.0);
  out_coord = vec4(gl_FragCoord.xyz, 1.0);
}
