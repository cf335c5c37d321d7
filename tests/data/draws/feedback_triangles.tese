#version 450 core
// feedback_quads.tese on the triangle domain, fractional even spacing, clockwise.
layout(triangles, fractional_even_spacing, cw) in;
in vec2 c_position[];
out vec3 f_coord;
flat out int f_patch;

void main() {
  f_coord = gl_TessCoord;
  f_patch = gl_PrimitiveID;
  gl_Position = vec4(gl_TessCoord.xy * 0.5 + c_position[0], gl_TessCoord.z * 0.5, 1.0);
}
