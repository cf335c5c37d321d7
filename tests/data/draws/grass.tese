#version 450 core
// Grass: isoline v is one blade, u runs from its root to its tip. Each blade's root lies on the
// ground patch at a place hashed from its line and patch number (integer arithmetic only, so
// that every implementation computes the same roots), and it bends toward +x.
layout(isolines, equal_spacing) in;
in vec3 c_position[];
out vec3 e_color;
uniform mat4 u_view_proj;
uniform float u_blades;
uniform float u_height;

uint mix_bits(uint h) {
  h ^= h >> 16u;
  h *= 0x7feb352du;
  h ^= h >> 15u;
  h *= 0x846ca68bu;
  return h ^ (h >> 16u);
}

void main() {
  const uint line = uint(round(gl_TessCoord.y * u_blades));
  const uint h = mix_bits(line * 2654435761u + uint(gl_PrimitiveID) * 40503u + 1u);
  const float r1 = float(h & 1023u) / 1023.0;
  const float r2 = float((h >> 10u) & 1023u) / 1023.0;
  const float r3 = float((h >> 20u) & 1023u) / 1023.0;
  const vec3 root = mix(mix(c_position[0], c_position[1], r1), mix(c_position[3], c_position[2], r1), r2);
  const float u = gl_TessCoord.x;
  const float height = u_height * (0.6 + 0.4 * r3);
  const vec3 p = root + vec3(0.35 * height * u * u, height * u, 0.1 * (r1 - 0.5) * u);
  e_color = mix(vec3(0.05, 0.25, 0.05), vec3(0.55, 0.85, 0.3), u);
  gl_Position = u_view_proj * vec4(p, 1.0);
}
