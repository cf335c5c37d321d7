#version 450 core
// One colour from uniforms of many GLSL types, set by their GL names: a nested struct with an
// array of structs, unsigned and boolean vectors, a double vector and non-square matrices.
struct Light {
  vec3 color;
  float power;
};
struct Rig {
  Light lights[2];
  mat2x3 m;
};
uniform Rig u_rig;
uniform uvec2 u_u;
uniform bvec3 u_b;
uniform dvec2 u_d;
uniform mat3x2 u_m32;
uniform int u_i[3];
layout(location = 0) out vec4 frag_color;

void main() {
  frag_color = vec4(u_rig.lights[1].color.g * u_rig.lights[0].power,
                    u_rig.m[1][2] + float(u_i[2]) / 16.0,
                    float(u_u.y) / 8.0 + (u_b.z ? 0.25 : 0.0),
                    float(u_d.y) + u_m32[2][1]);
}
