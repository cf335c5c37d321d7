#version 450
// Twin of PassThroughTcs (flat.h): gl_out[i] = gl_in[i], levels constant or adaptive.
// The runner sets N in layout(vertices = N) (default 3) to PassThroughTcs::vertices.
layout(vertices = 3) out;

// The vertex shader's outputs (stages/programs/transform.vert): attr[0], attr[1] of StageVertex.
layout(location = 0) in vec3 v_world_position[];
layout(location = 1) in vec3 v_world_normal[];
out StageVertex { vec4 attr[8]; } tcs_out[];

uniform bool u_adaptive;
uniform vec4 u_outer;                 // constant mode: gl_TessLevelOuter as is
uniform vec2 u_inner;                 // constant mode: gl_TessLevelInner as is
uniform mat4 u_view_proj;
uniform vec2 u_viewport;              // pixels
uniform float u_pixels_per_segment;
uniform float u_min_level;
uniform float u_max_level;
uniform int u_inner_rule;             // 0: max of outers, 1: mean

// Bit-pattern order of the endpoints: both patches of an edge compute its level alike.
bool bits_less(vec3 a, vec3 b) {
  uvec3 x = floatBitsToUint(a), y = floatBitsToUint(b);
  for (int i = 0; i < 3; ++i)
    if (x[i] != y[i]) return x[i] < y[i];
  return false;
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

void main() {
  int last = gl_PatchVerticesIn - 1;
  int src = min(gl_InvocationID, last);
  tcs_out[gl_InvocationID].attr[0] = vec4(v_world_position[src], 1.0);
  tcs_out[gl_InvocationID].attr[1] = vec4(v_world_normal[src], 0.0);
  for (int s = 2; s < 8; ++s) tcs_out[gl_InvocationID].attr[s] = vec4(0.0);
  if (gl_InvocationID == 0) {
    if (!u_adaptive) {
      gl_TessLevelOuter = float[4](u_outer.x, u_outer.y, u_outer.z, u_outer.w);
      gl_TessLevelInner = float[2](u_inner.x, u_inner.y);
    } else {
      vec3 p0 = v_world_position[0];
      vec3 p1 = v_world_position[min(1, last)];
      vec3 p2 = v_world_position[min(2, last)];
      float o0 = adaptive_edge_level(p1, p2);  // u = 0 edge
      float o1 = adaptive_edge_level(p2, p0);  // v = 0 edge
      float o2 = adaptive_edge_level(p0, p1);  // w = 0 edge
      float inner = u_inner_rule == 0 ? max(max(o0, o1), o2) : (o0 + o1 + o2) / 3.0;
      gl_TessLevelOuter = float[4](o0, o1, o2, 1.0);
      gl_TessLevelInner = float[2](inner, 1.0);
    }
  }
}
