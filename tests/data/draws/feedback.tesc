#version 450 core
// Fractional levels that differ from patch to patch, so that every patch tessellates otherwise.
layout(vertices = 4) out;
in vec2 v_position[];
out vec2 c_position[];

void main() {
  c_position[gl_InvocationID] = v_position[gl_InvocationID];
  float l = 1.0 + 0.7 * float(gl_PrimitiveID);
  gl_TessLevelOuter = float[4](l, l + 1.3, 2.0, 3.6);
  gl_TessLevelInner = float[2](l + 0.4, 2.9);
}
