#version 450 core
// storage.tese's patches, each evaluation also counting itself in texel (31, 31) of the r32ui image.
layout(quads, equal_spacing, ccw) in;
in vec2 c_position[];
layout(r32ui, binding = 0) uniform uimage2D u_counts;

void main() {
  imageAtomicAdd(u_counts, ivec2(31, 31), 1u);
  gl_Position = vec4(gl_TessCoord.xy * 0.5 + c_position[0], 0.0, 1.0);
}
