#version 450 core
// Height bands lit by a fixed light.
in vec3 e_normal;
in float e_height;
layout(location = 0) out vec4 frag_color;

void main() {
  const vec3 low = vec3(0.2, 0.45, 0.15), high = vec3(0.85, 0.8, 0.7);
  const float lambert = max(dot(normalize(e_normal), normalize(vec3(0.4, 1.0, 0.3))), 0.0);
  frag_color = vec4(mix(low, high, clamp(e_height, 0.0, 1.0)) * (0.3 + 0.7 * lambert), 1.0);
}
