#version 450 core
// Point mode: every domain point of a triangle patch, lifted onto a dome over the ground.
layout(triangles, fractional_odd_spacing, ccw, point_mode) in;
in vec3 c_position[];
out vec3 e_color;
uniform mat4 u_view_proj;

// main spelled as GLSL allows, with an early return: the capture wraps it without reading it.
void
main ( void )
{
  const vec3 b = gl_TessCoord;
  if (b.x < 0.0) return;
  vec3 p = b.x * c_position[0] + b.y * c_position[1] + b.z * c_position[2];
  const vec2 d = p.xz - vec2(3.0, 1.5);
  p.y += 2.0 - 0.2 * dot(d, d);
  e_color = b;
  gl_Position = u_view_proj * vec4(p, 1.0);
}
