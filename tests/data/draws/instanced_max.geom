#version 450 core
// Two invocations per triangle (gl_InvocationID 0 and 1), the second moved right; each emits a
// fourth vertex past max_vertices, which is dropped, so each emits one triangle. The colour
// says which input primitive (gl_PrimitiveIDIn) and invocation made it.
layout(triangles, invocations = 2) in;
layout(triangle_strip, max_vertices = 3) out;
out vec3 g_color;

void main() {
  for (int i = 0; i < 4; ++i) {
    gl_Position = gl_in[i % 3].gl_Position + vec4(0.6 * float(gl_InvocationID), 0.0, 0.0, 0.0);
    g_color = vec3(float(gl_PrimitiveIDIn % 16) / 15.0, float(gl_InvocationID), float(i) / 3.0);
    EmitVertex();
  }
}
