#version 450 core
// Side effects in every stage (storage_writes.json): each stage counts its invocations.
in vec2 in_position;
out vec2 v_position;
layout(std430, binding = 0) buffer Counters {
  uint vertices, patches, evaluations, fragments;
  int min_x;
  uint or_bits, xor_bits, swapped, last, max_y;
} counters;

void main() {
  v_position = in_position;
  atomicAdd(counters.vertices, 1u);
}
