#version 450
// Procedural displacement along the normal (seed 001, Figure 4): the flat patch moved by
// a * sin(f * |P|), its normal from the displaced surface's tangents. A user's evaluation shader
// on tessref's executor, with the built-in programs' twins for the other stages
// (scenes/displacement.json).
layout(triangles, fractional_odd_spacing, ccw) in;

in StageVertex { vec4 attr[8]; } tes_in[];  // the flat twin's control points: attr[0] position, attr[1] normal
layout(location = 0) out vec3 v_world_position;
layout(location = 1) out vec3 v_world_normal;

uniform mat4 u_view_proj;
uniform float u_amplitude;  // a
uniform float u_frequency;  // f

vec3 surface(vec3 b) {
  vec3 p = tes_in[0].attr[0].xyz * b.x + tes_in[1].attr[0].xyz * b.y + tes_in[2].attr[0].xyz * b.z;
  vec3 n = normalize(tes_in[0].attr[1].xyz * b.x + tes_in[1].attr[1].xyz * b.y + tes_in[2].attr[1].xyz * b.z);
  return p + u_amplitude * sin(u_frequency * length(p)) * n;
}

void main() {
  vec3 b = gl_TessCoord;
  vec3 p = surface(b);
  // Tangents by central differences in the domain (a step of 1/1024 of the patch).
  const float h = 1.0 / 1024.0;
  vec3 du = surface(b + vec3(h, -h, 0.0)) - surface(b - vec3(h, -h, 0.0));
  vec3 dv = surface(b + vec3(h, 0.0, -h)) - surface(b - vec3(h, 0.0, -h));
  v_world_position = p;
  v_world_normal = normalize(cross(du, dv));
  gl_Position = u_view_proj * vec4(p, 1.0);
}
