#version 450
// Twin of ScalarTaggedPnTcs (scalar_tagged_pn.h): PnTcs's net (pn_triangles.tesc) with the
// tangent coefficients and corner normals the per-vertex tags change (seed 001, Appendix B), and
// the corner order from the smooth normals (attr[5]). Evaluated by pn_triangles.tese.
layout(vertices = 3) out;

// The vertex shader's outputs (stages/programs/transform.vert): attr[0], attr[1] of StageVertex.
layout(location = 0) in vec3 v_world_position[];
layout(location = 1) in vec3 v_world_normal[];
layout(location = 2) in vec4 v_tags[];    // tagged_transform.vert: (tension, sharpness, bias, 0)
layout(location = 3) in vec3 v_crease[];  // world space; zero on smooth vertices
out StageVertex { vec4 attr[8]; } tcs_out[];
// [0] = b111, [1] = canonical corner order (as floats); slots as kPnPatch* in pn_triangles.h.
patch out vec4 pn_patch[16];

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

vec3 tangent_coefficient(vec3 pi, vec3 ni, vec3 pj) {
  float w = dot(pj - pi, ni);
  return (2.0 * pi + pj - w * ni) / 3.0;
}

// N' = normalize(N + s sigma Delta) on side s; N itself without sharpness.
vec3 sharp_normal(vec3 n, vec4 tags, vec3 crease, float side) {
  float sigma = tags.y;
  if (!(sigma > 0.0) || crease == vec3(0.0)) return n;
  return safe_normalize(n + crease * (side * sigma));
}

// Appendix B, Eq. 3: the coefficient next to P_j on the edge towards P_k.
vec3 tagged_coefficient(vec3 pj, vec3 nj, vec4 tags, vec3 crease, vec3 pk, bool crease_edge) {
  float theta = tags.x, sigma = tags.y, beta = tags.z;
  vec3 d = pj + (pk - pj) * ((1.0 - theta) / 3.0);
  if (crease_edge) {
    vec3 y = safe_normalize(nj + crease * beta);
    return d + y * -dot(nj, d - pj);
  }
  float side = dot(crease, pk - pj) >= 0.0 ? 1.0 : -1.0;
  vec3 x = safe_normalize(nj * (1.0 - sigma) + sharp_normal(nj, tags, crease, side));
  return d + x * -dot(x, d - pj);
}

bool pn_coefficient(vec4 tags, vec3 crease, bool crease_edge) {
  return tags.x == 0.0 && !crease_edge && !(tags.y > 0.0 && crease != vec3(0.0));
}

void main() {
  int id = gl_InvocationID;
  int j = (id + 1) % 3, k = (id + 2) % 3;
  vec3 pi = v_world_position[id];
  vec3 ni = safe_normalize(v_world_normal[id]);
  vec4 tags = v_tags[id];
  vec3 delta = v_crease[id];
  bool creased = delta != vec3(0.0);
  vec3 to_centroid = (v_world_position[j] - pi) + (v_world_position[k] - pi);
  tcs_out[gl_InvocationID].attr[0] = vec4(pi, 1.0);
  tcs_out[gl_InvocationID].attr[1] =
      vec4(sharp_normal(ni, tags, delta, dot(delta, to_centroid) >= 0.0 ? 1.0 : -1.0), 0.0);
  bool edge_j = creased && v_crease[j] != vec3(0.0);
  bool edge_k = creased && v_crease[k] != vec3(0.0);
  tcs_out[gl_InvocationID].attr[2] = vec4(pn_coefficient(tags, delta, edge_j)
      ? tangent_coefficient(pi, ni, v_world_position[j])
      : tagged_coefficient(pi, ni, tags, delta, v_world_position[j], edge_j), 1.0);
  tcs_out[gl_InvocationID].attr[3] = vec4(pn_coefficient(tags, delta, edge_k)
      ? tangent_coefficient(pi, ni, v_world_position[k])
      : tagged_coefficient(pi, ni, tags, delta, v_world_position[k], edge_k), 1.0);
  tcs_out[gl_InvocationID].attr[5] = vec4(ni, 0.0);  // the smooth normal: the corner order's
  for (int s = 6; s < 8; ++s) tcs_out[gl_InvocationID].attr[s] = vec4(0.0);
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

  barrier();  // phase 1 reads the other invocations' corners, normals and tangent coefficients

  vec3 mid = vec3(0.0);
  if (u_normal_mode == 1 || u_normal_mode == 2) {
    vec3 pj = tcs_out[j].attr[0].xyz, nj = tcs_out[j].attr[1].xyz;
    vec3 ni = tcs_out[id].attr[1].xyz;  // this corner's normal on the triangle's side
    bool swap_ab = corner_less(pj, nj, pi, ni);
    vec3 pa = swap_ab ? pj : pi, na = swap_ab ? nj : ni;
    vec3 pb = swap_ab ? pi : pj, nb = swap_ab ? ni : nj;
    vec3 d = pb - pa;
    float dd = dot(d, d);
    vec3 nsum = na + nb;
    float kf = u_normal_mode == 2 ? 4.0 : 2.0;
    float v = dd > 0.0 ? kf * dot(d, nsum) / dd : 0.0;
    vec3 h = nsum - v * d;
    mid = u_normal_mode == 2 ? h : safe_normalize(h);
  }
  tcs_out[gl_InvocationID].attr[4] = vec4(mid, 0.0);
  if (id == 0) {
    vec3 e = vec3(0.0), v = vec3(0.0);
    for (int c = 0; c < 3; ++c) {
      e += tcs_out[c].attr[2].xyz + tcs_out[c].attr[3].xyz;
      v += tcs_out[c].attr[0].xyz;
    }
    e /= 6.0;
    v /= 3.0;
    pn_patch[0] = vec4(e + (e - v) / 2.0, 1.0);
    vec3 ps[3] = vec3[3](tcs_out[0].attr[0].xyz, tcs_out[1].attr[0].xyz, tcs_out[2].attr[0].xyz);
    vec3 ns[3] = vec3[3](tcs_out[0].attr[5].xyz, tcs_out[1].attr[5].xyz, tcs_out[2].attr[5].xyz);
    int o[3] = int[3](0, 1, 2);
    int t;
    if (corner_less(ps[o[1]], ns[o[1]], ps[o[0]], ns[o[0]])) { t = o[0]; o[0] = o[1]; o[1] = t; }
    if (corner_less(ps[o[2]], ns[o[2]], ps[o[1]], ns[o[1]])) { t = o[1]; o[1] = o[2]; o[2] = t; }
    if (corner_less(ps[o[1]], ns[o[1]], ps[o[0]], ns[o[0]])) { t = o[0]; o[0] = o[1]; o[1] = t; }
    pn_patch[1] = vec4(float(o[0]), float(o[1]), float(o[2]), 0.0);
    for (int s = 2; s < 16; ++s) pn_patch[s] = vec4(0.0);
  }
}
