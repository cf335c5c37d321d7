#version 450 core
// A 3D sampler, which a 2D image cannot be bound to.
uniform sampler3D u_volume;
layout(location = 0) out vec4 frag_color;

void main() {
  frag_color = texture(u_volume, vec3(0.5));
}
