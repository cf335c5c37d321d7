#version 450 core
// A 4-vertex ground patch: u_blades isolines (blades) of u_segments segments each.
layout(vertices = 4) out;
in vec3 v_position[];
out vec3 c_position[];
uniform float u_blades;
uniform float u_segments;

void main() {
  c_position[gl_InvocationID] = v_position[gl_InvocationID];
  if (gl_InvocationID == 0) {
    gl_TessLevelOuter[0] = u_blades;
    gl_TessLevelOuter[1] = u_segments;
  }
}
