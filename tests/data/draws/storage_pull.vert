#version 450 core
// Vertex pulling: no vertex arrays; each control point is read from a shader storage block by
// gl_VertexID (three floats a point: a vec3[] would have std430's 16-byte stride).
layout(std430, binding = 0) readonly buffer ControlPoints {
  float xyz[];
};
out vec3 v_position;

void main() {
  const int i = 3 * gl_VertexID;
  v_position = vec3(xyz[i], xyz[i + 1], xyz[i + 2]);
}
