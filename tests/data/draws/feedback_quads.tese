#version 450 core
// Transform feedback's exact outputs: gl_TessCoord, the patch, and a position made of exact
// products (a multiplication by 0.5 and one addition: the same bits with or without fused
// multiply-add), so that only the primitive generator decides what the buffers hold.
layout(quads, fractional_odd_spacing, ccw) in;
in vec2 c_position[];
out vec3 f_coord;
flat out int f_patch;

void main() {
  f_coord = gl_TessCoord;
  f_patch = gl_PrimitiveID;
  gl_Position = vec4(gl_TessCoord.xy * 0.5 + c_position[0], 0.0, 1.0);
}
