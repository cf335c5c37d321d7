#version 450 core
// Each invocation takes the next record by an atomic counter and writes its domain point there:
// the records' order is the order the invocations ran in.
layout(quads, equal_spacing, ccw) in;
in vec2 c_position[];
layout(std430, binding = 0) buffer Counters {
  uint vertices, patches, evaluations, fragments;
  int min_x;
  uint or_bits, xor_bits, swapped, last, max_y;
} counters;
layout(std430, binding = 1) buffer Records {
  vec4 records[];
};

void main() {
  uint i = atomicAdd(counters.evaluations, 1u);
  records[i % uint(records.length())] = vec4(gl_TessCoord.xy, float(gl_PrimitiveID), float(i));
  gl_Position = vec4(gl_TessCoord.xy * 0.5 + c_position[0], 0.0, 1.0);
}
