#version 450 core
// Every fragment: its number in shading order into its pixel's word (the last fragment at a pixel
// wins), and each of GL's atomic operations on the counters. The derivative makes the quads'
// uncovered lanes run as helper invocations, which must change nothing.
layout(std430, binding = 0) buffer Counters {
  uint vertices, patches, evaluations, fragments;
  int min_x;
  uint or_bits, xor_bits, swapped, last, max_y;
} counters;
layout(std430, binding = 2) buffer Pixels {
  uint order[64 * 64];
} pixels;
out vec4 colour;

void main() {
  uint k = atomicAdd(counters.fragments, 1u);
  ivec2 p = ivec2(gl_FragCoord.xy);
  pixels.order[p.y * 64 + p.x] = k + 1u;
  atomicMin(counters.min_x, p.x - 1000);
  atomicMax(counters.max_y, uint(p.y));
  atomicOr(counters.or_bits, 1u << uint(p.x & 31));
  atomicXor(counters.xor_bits, uint(p.y * 64 + p.x));
  atomicCompSwap(counters.swapped, k, k + 1u);
  atomicExchange(counters.last, k);
  colour = vec4(float(k & 255u) / 255.0, dFdx(gl_FragCoord.x), 0.0, 1.0);
}
