#version 450
// Twin of PnTes (pn_triangles.h). gl_TessCoord.x, .y, .z weigh gl_in[0], [1], [2] (the paper's
// w, u, v for P1, P2, P3). The runner rewrites the spacing/winding/point_mode in the layout line.
layout(triangles, fractional_odd_spacing, ccw) in;

in StageVertex { vec4 attr[8]; } tes_in[];
patch in vec4 pn_patch[16];
layout(location = 0) out vec3 v_world_position;  // varyings[0..2]
layout(location = 1) out vec3 v_world_normal;    // varyings[3..5]

uniform int u_normal_mode;  // 0 linear, 1 quadratic, 2 quadratic_corrected, 3 analytic
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

vec3 P(int i) { return tes_in[i].attr[0].xyz; }
vec3 N(int i) { return tes_in[i].attr[1].xyz; }
// Tangent coefficient at corner x towards corner y.
vec3 B(int x, int y) { return y == (x + 1) % 3 ? tes_in[x].attr[2].xyz : tes_in[x].attr[3].xyz; }
// Mid-edge normal coefficient of the edge {x, y}.
vec3 M(int x, int y) { return y == (x + 1) % 3 ? tes_in[x].attr[4].xyz : tes_in[y].attr[4].xyz; }

void main() {
  vec3 tc = gl_TessCoord;
  // Canonical corner order (clamped like the C++ reader); terms summed in it, so a shared edge
  // evaluates with the same operations in both of its patches.
  int x = clamp(int(pn_patch[1].x), 0, 2), y = clamp(int(pn_patch[1].y), 0, 2),
      z = clamp(int(pn_patch[1].z), 0, 2);
  float a = tc[x], b = tc[y], c = tc[z];
  vec3 p = P(x) * (a * a * a);
  p += P(y) * (b * b * b);
  p += P(z) * (c * c * c);
  p += B(x, y) * (3.0 * a * a * b);
  p += B(y, x) * (3.0 * a * b * b);
  p += B(y, z) * (3.0 * b * b * c);
  p += B(z, y) * (3.0 * b * c * c);
  p += B(x, z) * (3.0 * a * a * c);
  p += B(z, x) * (3.0 * a * c * c);
  p += pn_patch[0].xyz * (6.0 * a * b * c);
  p += vec3(0.0);

  vec3 lin = N(x) * a + N(y) * b + N(z) * c;
  vec3 n;
  if (u_normal_mode == 0) {
    n = safe_normalize(lin);
  } else if (u_normal_mode == 1 || u_normal_mode == 2) {
    vec3 q = N(x) * (a * a);
    q += N(y) * (b * b);
    q += N(z) * (c * c);
    q += M(x, y) * (a * b);
    q += M(y, z) * (b * c);
    q += M(x, z) * (a * c);
    n = safe_normalize(q);
  } else {
    // Derivatives along the domain: d1 moves weight from gl_in[0] to [1], d2 from [0] to [2].
    vec3 b300 = P(0), b030 = P(1), b003 = P(2);
    vec3 b210 = B(0, 1), b201 = B(0, 2), b021 = B(1, 2), b120 = B(1, 0);
    vec3 b102 = B(2, 0), b012 = B(2, 1), b111 = pn_patch[0].xyz;
    float s = tc.x, t = tc.y, u = tc.z;
    float w200 = s * s, w020 = t * t, w002 = u * u;
    float w110 = 2.0 * s * t, w011 = 2.0 * t * u, w101 = 2.0 * s * u;
    vec3 d1 = 3.0 * ((b210 - b300) * w200 + (b030 - b120) * w020 + (b012 - b102) * w002 +
                     (b120 - b210) * w110 + (b021 - b111) * w011 + (b111 - b201) * w101);
    vec3 d2 = 3.0 * ((b201 - b300) * w200 + (b021 - b120) * w020 + (b003 - b102) * w002 +
                     (b111 - b210) * w110 + (b012 - b111) * w011 + (b102 - b201) * w101);
    n = safe_normalize(cross(d1, d2));
    if (n == vec3(0.0)) n = safe_normalize(lin);   // degenerate tangents
    else if (dot(n, lin) < 0.0) n = -n;            // orient like the input normals
  }
  n += vec3(0.0);
  if (u_displacement) displace(p, n);
  v_world_position = p;
  v_world_normal = n;
  gl_Position = u_view_proj * vec4(p, 1.0);
}
