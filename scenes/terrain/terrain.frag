#version 450 core
// Ground colour from a mip-mapped texture (implicit level of detail from the quad's derivatives),
// lit by one light and shadowed through a depth texture: the shadow sampler compares each of the
// four nearest texels with the fragment's depth as the light sees it (GL_LEQUAL) and filters the
// results (GL_LINEAR), which softens the shadow's edge by one shadow-map texel.
in vec2 e_uv;
in vec3 e_normal;
in vec4 e_light;
layout(location = 0) out vec4 frag_color;
uniform sampler2D u_albedo;
uniform sampler2DShadow u_shadow;
uniform vec3 u_light_dir;    // towards the light
uniform float u_depth_bias;  // against self-shadowing: the map holds the depth at texel centres

void main() {
  const vec3 albedo = texture(u_albedo, e_uv * 4.0).rgb;
  const vec3 light = e_light.xyz / e_light.w * 0.5 + 0.5;
  const float lit = texture(u_shadow, vec3(light.xy, light.z - u_depth_bias));
  const float lambert = max(dot(normalize(e_normal), u_light_dir), 0.0);
  frag_color = vec4(albedo * (0.25 + 0.75 * lambert * lit), 1.0);
}
