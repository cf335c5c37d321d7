#version 450 core
// Quad patches at a fixed level.
layout(vertices = 4) out;
in vec3 v_position[];
in vec4 v_color[];
out vec3 c_position[];
out vec4 c_color[];

void main() {
  c_position[gl_InvocationID] = v_position[gl_InvocationID];
  c_color[gl_InvocationID] = v_color[gl_InvocationID];
  if (gl_InvocationID == 0) {
    gl_TessLevelOuter[0] = 8.0;
    gl_TessLevelOuter[1] = 8.0;
    gl_TessLevelOuter[2] = 8.0;
    gl_TessLevelOuter[3] = 8.0;
    gl_TessLevelInner[0] = 8.0;
    gl_TessLevelInner[1] = 8.0;
  }
}
