#version 450 core
// One control point per patch; the patch's tessellation levels come from a buffer indexed by
// the patch's index in the whole capture (gl_PrimitiveID restarts at 0 with every draw).
layout(vertices = 1) out;

// Two vec4 per patch: (outer0, outer1, outer2, outer3), (inner0, inner1, unused, unused).
// Raw float bits: NaN, infinities and negative levels reach the generator unchanged.
layout(std430, binding = 0) readonly buffer TessLevelBuffer { vec4 levels[]; };
uniform int u_patch_base;

void main() {
  int index = u_patch_base + gl_PrimitiveID;
  vec4 outer = levels[2 * index];
  vec4 inner = levels[2 * index + 1];
  gl_TessLevelOuter[0] = outer.x;
  gl_TessLevelOuter[1] = outer.y;
  gl_TessLevelOuter[2] = outer.z;
  gl_TessLevelOuter[3] = outer.w;
  gl_TessLevelInner[0] = inner.x;
  gl_TessLevelInner[1] = inner.y;
  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
}
