#version 450 core
// Writes gl_FragDepth: the interpolated depth moved by a triangle wave along x (exact in float on
// both sides), pushed below 0 on the left and above 1 on the right, where the buffer's format
// decides what is stored (clamped for a fixed-point buffer).
layout(depth_any) out float gl_FragDepth;
in vec3 e_normal;
layout(location = 0) out vec4 frag_color;

void main() {
  frag_color = vec4(0.5 * normalize(e_normal) + 0.5, 1.0);
  float wave = abs(fract(gl_FragCoord.x / 16.0) - 0.5) * 0.004;
  float shift = gl_FragCoord.x < 80.0 ? -1.5 : (gl_FragCoord.x > 180.0 ? 1.5 : 0.0);
  gl_FragDepth = gl_FragCoord.z + wave + shift;
}
