#version 450 core
// Quad patches tessellated by distance: each edge's level from its midpoint's distance to the eye,
// so the two patches that share an edge give it the same level (no cracks).
layout(vertices = 4) out;
in vec3 v_position[];
out vec3 c_position[];
uniform vec3 u_eye;
uniform float u_detail;  // level at distance 1

float edge_level(vec3 a, vec3 b) {
  return clamp(u_detail / distance(0.5 * (a + b), u_eye), 2.0, 48.0);
}

void main() {
  c_position[gl_InvocationID] = v_position[gl_InvocationID];
  if (gl_InvocationID == 0) {
    // GL's quad edges: outer 0 is u = 0 (corners 0 and 3), 1 is v = 0 (0 and 1), 2 is u = 1
    // (1 and 2), 3 is v = 1 (3 and 2).
    gl_TessLevelOuter[0] = edge_level(v_position[0], v_position[3]);
    gl_TessLevelOuter[1] = edge_level(v_position[0], v_position[1]);
    gl_TessLevelOuter[2] = edge_level(v_position[1], v_position[2]);
    gl_TessLevelOuter[3] = edge_level(v_position[3], v_position[2]);
    gl_TessLevelInner[0] = max(gl_TessLevelOuter[1], gl_TessLevelOuter[3]);
    gl_TessLevelInner[1] = max(gl_TessLevelOuter[0], gl_TessLevelOuter[2]);
  }
}
