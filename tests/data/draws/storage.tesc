#version 450 core
// Levels 2, 3, 4 and 5 (equal spacing) for patches 0 to 3; invocation 0 counts the patch.
layout(vertices = 4) out;
in vec2 v_position[];
out vec2 c_position[];
layout(std430, binding = 0) buffer Counters {
  uint vertices, patches, evaluations, fragments;
  int min_x;
  uint or_bits, xor_bits, swapped, last, max_y;
} counters;

void main() {
  c_position[gl_InvocationID] = v_position[gl_InvocationID];
  float l = float(2 + gl_PrimitiveID);
  gl_TessLevelOuter = float[4](l, l, l, l);
  gl_TessLevelInner = float[2](l, l);
  if (gl_InvocationID == 0) atomicAdd(counters.patches, 1u);
}
