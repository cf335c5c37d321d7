#version 450 core
// Captured by transform feedback, interleaved: the domain point exactly as generated, and the
// patch it belongs to (checked on readback: llvmpipe mixes up patches when a draw wraps its
// 16-bit TES vertex indices). The layout line is rewritten from the TessLayout at run time.
layout(triangles, equal_spacing, ccw) in;

out vec3 tess_coord;
out int patch_id;
uniform int u_patch_base;

void main() {
  tess_coord = gl_TessCoord;
  patch_id = u_patch_base + gl_PrimitiveID;
  gl_Position = vec4(gl_TessCoord, 1.0);
}
