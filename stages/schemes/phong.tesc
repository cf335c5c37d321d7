#version 450
// Twin of PhongTcs (phong.h, over QuadraticTcs in quadratic_patch.h): the quadratic net of Phong
// tessellation and the mid-edge normals. gl_in[0], [1], [2] are the papers' p0, p1, p2.
layout(vertices = 3) out;

// The vertex shader's outputs (stages/programs/transform.vert): attr[0], attr[1] of StageVertex.
layout(location = 0) in vec3 v_world_position[];
layout(location = 1) in vec3 v_world_normal[];
out StageVertex { vec4 attr[8]; } tcs_out[];
// [0] = canonical corner order (as floats); slots as kQuad* in quadratic_patch.h.
patch out vec4 quad_patch[16];

uniform int u_normal_mode;            // 0 linear, 1 quadratic, 2 quadratic_corrected, 3 analytic
uniform bool u_adaptive;
uniform vec4 u_outer;                 // constant mode: gl_TessLevelOuter as is
uniform vec2 u_inner;                 // constant mode: gl_TessLevelInner as is
uniform mat4 u_view_proj;
uniform vec2 u_viewport;              // pixels
uniform float u_pixels_per_segment;
uniform float u_min_level;
uniform float u_max_level;
uniform int u_inner_rule;             // 0: max of outers, 1: mean

vec3 safe_normalize(vec3 v) {
  float len2 = dot(v, v);
  if (!(len2 > 0.0) || isinf(len2) || isnan(len2)) return vec3(0.0);
  return v / sqrt(len2);
}

bool bits_less(vec3 a, vec3 b) {
  uvec3 x = floatBitsToUint(a), y = floatBitsToUint(b);
  for (int i = 0; i < 3; ++i)
    if (x[i] != y[i]) return x[i] < y[i];
  return false;
}

bool corner_less(vec3 pa, vec3 na, vec3 pb, vec3 nb) {
  if (floatBitsToUint(pa) != floatBitsToUint(pb)) return bits_less(pa, pb);
  return bits_less(na, nb);
}

float adaptive_edge_level(vec3 a_in, vec3 b_in) {
  bool swap_ab = bits_less(b_in, a_in);
  vec3 a = swap_ab ? b_in : a_in;
  vec3 b = swap_ab ? a_in : b_in;
  vec4 ca = u_view_proj * vec4(a, 1.0);
  vec4 cb = u_view_proj * vec4(b, 1.0);
  if (isnan(ca.w) || isnan(cb.w)) return uintBitsToFloat(0x7fc00000u);
  if (ca.w <= 0.0 || cb.w <= 0.0) return u_max_level;
  vec2 half_vp = u_viewport * 0.5;
  vec2 wa = vec2(ca.x / ca.w, ca.y / ca.w) * half_vp;
  vec2 wb = vec2(cb.x / cb.w, cb.y / cb.w) * half_vp;
  vec2 d = wb - wa;
  float level = sqrt(d.x * d.x + d.y * d.y) / u_pixels_per_segment;
  if (isnan(level)) return level;
  return min(max(level, u_min_level), u_max_level);
}

// Quadratic normal patch: the mid-edge normal coefficient (bezier_nets.h: quadratic_normal_mid).
vec3 quadratic_normal_mid(vec3 p0, vec3 n0, vec3 p1, vec3 n1, bool corrected) {
  vec3 d = p1 - p0;
  float dd = dot(d, d);
  vec3 nsum = n0 + n1;
  float k = corrected ? 4.0 : 2.0;
  float v = dd > 0.0 ? k * dot(d, nsum) / dd : 0.0;
  return nsum - v * d;
}

// ---- The scheme's edge rule (bezier_nets.h: phong_edge_point), operation for operation.
uniform float u_phong_alpha;

vec3 tangent_plane_projection(vec3 q, vec3 p, vec3 n) { return q - dot(q - p, n) * n; }

vec3 edge_point(vec3 p0, vec3 n0, vec3 p1, vec3 n1) {
  vec3 mid = (p0 + p1) / 2.0;
  vec3 projected = (tangent_plane_projection(p1, p0, n0) + tangent_plane_projection(p0, p1, n1)) / 2.0;
  return mid + u_phong_alpha * (projected - mid);
}
// ----

void main() {
  int id = gl_InvocationID;
  tcs_out[gl_InvocationID].attr[0] = vec4(v_world_position[id], 1.0);
  tcs_out[gl_InvocationID].attr[1] = vec4(safe_normalize(v_world_normal[id]), 0.0);
  for (int s = 4; s < 8; ++s) tcs_out[gl_InvocationID].attr[s] = vec4(0.0);
  if (id == 0) {
    if (!u_adaptive) {
      gl_TessLevelOuter = float[4](u_outer.x, u_outer.y, u_outer.z, u_outer.w);
      gl_TessLevelInner = float[2](u_inner.x, u_inner.y);
    } else {
      vec3 p0 = v_world_position[0], p1 = v_world_position[1], p2 = v_world_position[2];
      float o0 = adaptive_edge_level(p1, p2);  // u = 0 edge
      float o1 = adaptive_edge_level(p2, p0);  // v = 0 edge
      float o2 = adaptive_edge_level(p0, p1);  // w = 0 edge
      float inner = u_inner_rule == 0 ? max(max(o0, o1), o2) : (o0 + o1 + o2) / 3.0;
      gl_TessLevelOuter = float[4](o0, o1, o2, 1.0);
      gl_TessLevelInner = float[2](inner, 1.0);
    }
  }

  barrier();  // phase 1 reads the other invocations' corners and normals

  int j = (id + 1) % 3;
  vec3 pi = tcs_out[id].attr[0].xyz, ni = tcs_out[id].attr[1].xyz;
  vec3 pj = tcs_out[j].attr[0].xyz, nj = tcs_out[j].attr[1].xyz;
  tcs_out[gl_InvocationID].attr[2] = vec4(edge_point(pi, ni, pj, nj), 1.0);
  vec3 mid = vec3(0.0);
  if (u_normal_mode == 1 || u_normal_mode == 2) {
    vec3 h = quadratic_normal_mid(pi, ni, pj, nj, u_normal_mode == 2);
    mid = u_normal_mode == 2 ? h : safe_normalize(h);
  }
  tcs_out[gl_InvocationID].attr[3] = vec4(mid, 0.0);
  if (id == 0) {
    vec3 ps[3] = vec3[3](tcs_out[0].attr[0].xyz, tcs_out[1].attr[0].xyz, tcs_out[2].attr[0].xyz);
    vec3 ns[3] = vec3[3](tcs_out[0].attr[1].xyz, tcs_out[1].attr[1].xyz, tcs_out[2].attr[1].xyz);
    int o[3] = int[3](0, 1, 2);
    int t;
    if (corner_less(ps[o[1]], ns[o[1]], ps[o[0]], ns[o[0]])) { t = o[0]; o[0] = o[1]; o[1] = t; }
    if (corner_less(ps[o[2]], ns[o[2]], ps[o[1]], ns[o[1]])) { t = o[1]; o[1] = o[2]; o[2] = t; }
    if (corner_less(ps[o[1]], ns[o[1]], ps[o[0]], ns[o[0]])) { t = o[0]; o[0] = o[1]; o[1] = t; }
    quad_patch[0] = vec4(float(o[0]), float(o[1]), float(o[2]), 0.0);
    for (int s = 1; s < 16; ++s) quad_patch[s] = vec4(0.0);
  }
}
