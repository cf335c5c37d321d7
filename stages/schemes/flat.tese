#version 450
// Twin of FlatTes (flat.h). The runner rewrites the layout line from the TessLayout (glsl_name())
// and, for quads or isolines, inserts "#define TESSREF_QUADS" / "#define TESSREF_ISOLINES".
layout(triangles, equal_spacing, ccw) in;

in StageVertex { vec4 attr[8]; } tes_in[];
layout(location = 0) out vec3 v_world_position;  // varyings[0..2]
layout(location = 1) out vec3 v_world_normal;    // varyings[3..5]

uniform mat4 u_view_proj;

vec3 safe_normalize(vec3 v) {
  float len2 = dot(v, v);
  if (!(len2 > 0.0) || isinf(len2) || isnan(len2)) return vec3(0.0);
  return v / sqrt(len2);
}

// Procedural displacement along the normal (stages/schemes/displacement.h), operation for
// operation displace() there; off unless the scene has tessellation.displacement.
uniform bool u_displacement;
uniform float u_displacement_amplitude;  // a
uniform float u_displacement_frequency;  // f

void displace(inout vec3 p, inout vec3 n) {
  if (n == vec3(0.0)) return;
  float a = u_displacement_amplitude, f = u_displacement_frequency;
  float r = sqrt(dot(p, p));
  float s = sin(f * r), c = cos(f * r);
  vec3 g = r > 0.0 ? p * (a * f * c / r) : vec3(0.0);  // the gradient of |P| is P / |P|
  vec3 tangential = g - n * dot(g, n);
  p = p + n * (a * s) + vec3(0.0);
  n = safe_normalize(n - tangential) + vec3(0.0);
}

bool corner_less(vec3 pa, vec3 na, vec3 pb, vec3 nb) {
  uvec3 xa = floatBitsToUint(pa), xb = floatBitsToUint(pb);
  for (int i = 0; i < 3; ++i)
    if (xa[i] != xb[i]) return xa[i] < xb[i];
  uvec3 ya = floatBitsToUint(na), yb = floatBitsToUint(nb);
  for (int i = 0; i < 3; ++i)
    if (ya[i] != yb[i]) return ya[i] < yb[i];
  return false;
}

void main() {
  vec3 p, n;
#if defined(TESSREF_QUADS)
  float u = gl_TessCoord.x, v = gl_TessCoord.y;
  float a = (1.0 - u) * (1.0 - v), b = u * (1.0 - v), c = u * v, d = (1.0 - u) * v;
  p = tes_in[0].attr[0].xyz * a + tes_in[1].attr[0].xyz * b + tes_in[2].attr[0].xyz * c +
      tes_in[3].attr[0].xyz * d;
  n = tes_in[0].attr[1].xyz * a + tes_in[1].attr[1].xyz * b + tes_in[2].attr[1].xyz * c +
      tes_in[3].attr[1].xyz * d;
#elif defined(TESSREF_ISOLINES)
  float u = gl_TessCoord.x;
  p = tes_in[0].attr[0].xyz * (1.0 - u) + tes_in[1].attr[0].xyz * u;
  n = tes_in[0].attr[1].xyz * (1.0 - u) + tes_in[1].attr[1].xyz * u;
#else
  // gl_TessCoord.x, .y, .z weigh gl_in[0], [1], [2]; summed in the canonical corner order.
  vec3 ps[3] = vec3[3](tes_in[0].attr[0].xyz, tes_in[1].attr[0].xyz, tes_in[2].attr[0].xyz);
  vec3 ns[3] = vec3[3](tes_in[0].attr[1].xyz, tes_in[1].attr[1].xyz, tes_in[2].attr[1].xyz);
  int o[3] = int[3](0, 1, 2);
  int t;
  if (corner_less(ps[o[1]], ns[o[1]], ps[o[0]], ns[o[0]])) { t = o[0]; o[0] = o[1]; o[1] = t; }
  if (corner_less(ps[o[2]], ns[o[2]], ps[o[1]], ns[o[1]])) { t = o[1]; o[1] = o[2]; o[2] = t; }
  if (corner_less(ps[o[1]], ns[o[1]], ps[o[0]], ns[o[0]])) { t = o[0]; o[0] = o[1]; o[1] = t; }
  p = ps[o[0]] * gl_TessCoord[o[0]] + ps[o[1]] * gl_TessCoord[o[1]] + ps[o[2]] * gl_TessCoord[o[2]];
  n = ns[o[0]] * gl_TessCoord[o[0]] + ns[o[1]] * gl_TessCoord[o[1]] + ns[o[2]] * gl_TessCoord[o[2]];
  p += vec3(0.0);
  n += vec3(0.0);
#endif
  n = safe_normalize(n);
  if (u_displacement) displace(p, n);
  v_world_position = p;
  v_world_normal = n;
  gl_Position = u_view_proj * vec4(p, 1.0);
}
