#version 450 core
// Per instance, the patch is scaled and moved by its entry of a uniform struct array.
layout(location = 0) in vec3 in_position;  // GL_SHORT, normalized
layout(location = 1) in vec4 in_color;     // GL_UNSIGNED_BYTE, normalized, interleaved
struct Instance {
  vec3 offset;
  float scale;
  vec4 tint;
};
uniform Instance u_instances[3];
out vec3 v_position;
out vec4 v_color;

void main() {
  const Instance inst = u_instances[gl_InstanceID];
  v_position = in_position * inst.scale + inst.offset;
  v_color = in_color * inst.tint;
}
