#version 450 core
// Lambert with the block's light, ambient term and colour matrix.
in vec3 e_normal;
in vec4 e_color;
layout(location = 0) out vec4 frag_color;
layout(std140, binding = 1) uniform Shading {
  vec3 light_dir;
  float ambient;
  mat3 tint_matrix;
  float bulge[3];
  vec2 spare;
};

void main() {
  const float lambert = max(dot(normalize(e_normal), normalize(light_dir)), 0.0);
  const vec3 c = tint_matrix * e_color.rgb;
  frag_color = vec4(c * (ambient + (1.0 - ambient) * lambert) + vec3(spare, 0.0), 1.0);
}
