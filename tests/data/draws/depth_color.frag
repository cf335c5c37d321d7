#version 450 core
// The normal as red and green, the window depth as blue: where depth is clamped, blue is flat.
in vec3 e_normal;
layout(location = 0) out vec4 frag_color;

void main() {
  vec3 n = 0.5 * normalize(e_normal) + 0.5;
  frag_color = vec4(n.x, n.y, gl_FragCoord.z, 1.0);
}
