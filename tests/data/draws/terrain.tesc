#version 450 core
// 4-vertex quad patches at one level.
layout(vertices = 4) out;
in vec3 v_position[];
out vec3 c_position[];
uniform float u_level;

void main() {
  c_position[gl_InvocationID] = v_position[gl_InvocationID];
  if (gl_InvocationID == 0) {
    gl_TessLevelOuter[0] = u_level;
    gl_TessLevelOuter[1] = u_level;
    gl_TessLevelOuter[2] = u_level;
    gl_TessLevelOuter[3] = u_level;
    gl_TessLevelInner[0] = u_level;
    gl_TessLevelInner[1] = u_level;
  }
}
