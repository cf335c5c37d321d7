#version 450 core
// Images read and written by every fragment (image_writes.json): an r32ui image (the height map's
// 8-bit values as integers) takes atomics, the fragment's own texel and the texel a 2 x 2 block of
// fragments shares; an r32f image (the same values as floats) is read and overwritten. dFdx makes the quads' uncovered lanes
// helper invocations, which must change nothing.
layout(r32ui, binding = 0) uniform uimage2D u_counts;
layout(r32f, binding = 1) uniform image2D u_colour;
out vec4 colour;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  uint before = imageAtomicAdd(u_counts, p, 1000u);
  imageAtomicMax(u_counts, p / 2 + ivec2(16, 0), before);
  imageAtomicCompSwap(u_counts, ivec2(0, 31), uint(p.x), uint(p.y));
  vec4 c = imageLoad(u_colour, p);
  imageStore(u_colour, p, vec4(float(before) + c.r * float(imageSize(u_colour).x) + dFdx(gl_FragCoord.x)));
  colour = vec4(c.rgb, 1.0);
}
