#version 450
// Twin of QuadraticTes (quadratic_patch.h), the evaluation program of Phong tessellation, NLSA and
// Nagata triangles. gl_TessCoord.x, .y, .z weigh gl_in[0], [1], [2] (the papers' p0, p1, p2).
// The runner rewrites the spacing/winding/point_mode in the layout line.
layout(triangles, fractional_odd_spacing, ccw) in;

in StageVertex { vec4 attr[8]; } tes_in[];
patch in vec4 quad_patch[16];
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
// Mid-edge control point and mid-edge normal of the edge {i, j}.
vec3 B(int i, int j) { return j == (i + 1) % 3 ? tes_in[i].attr[2].xyz : tes_in[j].attr[2].xyz; }
vec3 M(int i, int j) { return j == (i + 1) % 3 ? tes_in[i].attr[3].xyz : tes_in[j].attr[3].xyz; }

void main() {
  vec3 tc = gl_TessCoord;
  // Canonical corner order (clamped like the C++ reader); terms summed in it, so a shared edge
  // evaluates with the same operations in both of its patches.
  int x = clamp(int(quad_patch[0].x), 0, 2), y = clamp(int(quad_patch[0].y), 0, 2),
      z = clamp(int(quad_patch[0].z), 0, 2);
  float a = tc[x], b = tc[y], c = tc[z];
  vec3 p = P(x) * (a * a);
  p += P(y) * (b * b);
  p += P(z) * (c * c);
  p += B(x, y) * (2.0 * a * b);
  p += B(y, z) * (2.0 * b * c);
  p += B(x, z) * (2.0 * a * c);
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
    vec3 b200 = P(0), b020 = P(1), b002 = P(2);
    vec3 b110 = B(0, 1), b011 = B(1, 2), b101 = B(0, 2);
    float s = tc.x, t = tc.y, u = tc.z;
    vec3 d1 = 2.0 * ((b110 - b200) * s + (b020 - b110) * t + (b011 - b101) * u);
    vec3 d2 = 2.0 * ((b101 - b200) * s + (b011 - b110) * t + (b002 - b101) * u);
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
