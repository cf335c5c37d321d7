#include "texture/cube.h"

#include <bit>
#include <cmath>
#include <cstdint>

#include "texture/sampler_ops.h"

namespace tessref::texture {
namespace {

using namespace ops;

constexpr std::uint32_t kSign = 0x80000000u;

float flip(float x, std::uint32_t sign) { return std::bit_cast<float>(std::bit_cast<std::uint32_t>(x) ^ sign); }

// The major axis (0, 1, 2 for x, y, z) and the sign bit of its coordinate: z on ties, then y.
struct Major {
  int axis;
  std::uint32_t sign;
};
Major major_axis(const float dir[3]) {
  const float as = std::fabs(dir[0]), at = std::fabs(dir[1]), ar = std::fabs(dir[2]);
  const int axis = ar >= max_ps(as, at) ? 2 : as > at ? 0 : 1;
  return {axis, std::bit_cast<std::uint32_t>(dir[axis]) & kSign};
}

// GL 4.6 table 8.19 as sign flips of (s, t, r) = (x, y, z): the face's (s_c, t_c).
void face_coords(const Major& m, const float v[3], float& sc, float& tc) {
  switch (m.axis) {
    case 0: sc = flip(v[2], kSign ^ m.sign), tc = flip(v[1], kSign); break;
    case 1: sc = v[0], tc = flip(v[2], m.sign); break;
    default: sc = flip(v[0], m.sign), tc = flip(v[1], kSign); break;
  }
}

int face_of(const Major& m) { return 2 * m.axis + (m.sign ? 1 : 0); }

// Where GL_LINEAR's four texels lie on a seamless cube map (lp_build_sample_image_linear's
// seamless branch): x0, x1, y0, y1 unwrapped, the weights, and which edges they fall off
// (x0 < 0, x1 > max, y0 < 0, y1 > max).
struct Footprint {
  i32 x0, x1, y0, y1;
  float ws, wt;
  bool off[4];
  bool corner() const { return (off[0] || off[1]) && (off[2] || off[3]); }
  // Whether texel k (x0 y0, x1 y0, x0 y1, x1 y1) is the one a corner lacks.
  bool missing(int k) const { return off[k & 1] && off[2 + (k >> 1)]; }
};
Footprint footprint(int size, const CubeFace& at) {
  Footprint f;
  const float wf = float(size);
  auto floor_fract = [](float c, i32& i, float& w) {
    const float fl = std::floor(c);
    i = fptosi(fl);
    w = c - fl;
  };
  // max(c, 0) with NaN to 0 (GALLIVM_NAN_RETURN_OTHER_SECOND_NONNAN), in texels, less half a texel.
  // A face coordinate is at most 1 but where 0.5 / |m_a| overflows (a denormal m_a): kept to the
  // face there, where llvmpipe would read outside the level.
  auto texels = [&](float c) { return min_ps((std::fmax(c, 0.0f) * wf) - 0.5f, wf - 0.5f); };
  floor_fract(texels(at.s), f.x0, f.ws);
  floor_fract(texels(at.t), f.y0, f.wt);
  f.x1 = add(f.x0, 1);
  f.y1 = add(f.y0, 1);
  const i32 max = size - 1;
  f.off[0] = f.x0 < 0;
  f.off[1] = f.x1 > max;
  f.off[2] = f.y0 < 0;
  f.off[3] = f.y1 > max;
  return f;
}

// A texel of the footprint: its face and its (x, y) there.
struct TexelAt {
  i32 face, x, y;
};

// The footprint's four texels in Mesa's order (x0 y0, x1 y0, x0 y1, x1 y1), those that fall off
// the face taken from its neighbour (lp_build_cube_new_coords). A texel that falls off both x and
// y (a corner) is read from the x neighbour at the clamped y: its weight goes to the other three,
// or, on the vector's interpolating path, it is filtered as it is.
std::array<TexelAt, 4> footprint_texels(const Footprint& f, int size, int face) {
  const i32 max = size - 1;
  const i32 y0c = std::max(f.y0, 0), y1c = std::min(f.y1, max);
  if (!(f.off[0] || f.off[1] || f.off[2] || f.off[3]))
    return {{{face, f.x0, f.y0}, {face, f.x1, f.y0}, {face, f.x0, f.y1}, {face, f.x1, f.y1}}};
  // The neighbours (for faces 0 to 5): x < 0: 4 5 1 1 1 0; x > max: 5 4 0 0 0 1; y < 0: 2 2 5 4 2 2;
  // y > max: 3 3 4 5 3 3.
  const bool f23 = (face & ~4) > 1, f2 = face == 2, odd = face & 1;
  i32 next_face[4];
  next_face[0] = face > 1 ? (face == 5 ? 0 : 1) : 4 + odd;
  next_face[1] = next_face[0] ^ 1;
  next_face[3] = f23 ? face + 2 : 3;
  next_face[2] = next_face[3] ^ 1;
  // New coordinates [edge][lower or higher of the other axis's pair].
  i32 nx[4][2], ny[4][2];
  const i32 ys[2] = {y0c, y1c}, xs[2] = {f.x0, f.x1};
  for (int k = 0; k < 2; ++k) {
    nx[1][k] = f23 ? (f2 ? max - ys[k] : ys[k]) : 0;
    nx[0][k] = max - nx[1][k];
    nx[3][k] = face > 1 ? (odd ? max - xs[k] : xs[k]) : (odd ? 0 : max);
    nx[2][k] = f23 ? max - nx[3][k] : nx[3][k];
    ny[0][k] = f23 ? (f2 ? 0 : max) : ys[k];
    ny[1][k] = ny[0][k];
    ny[3][k] = face > 1 ? (odd ? max : 0) : (odd ? max - xs[k] : xs[k]);
    ny[2][k] = f23 ? ny[3][k] : max - ny[3][k];
  }
  TexelAt t00{f.off[0] ? next_face[0] : face, f.off[0] ? nx[0][0] : f.x0, f.off[0] ? ny[0][0] : y0c};
  TexelAt t10{f.off[0] ? next_face[0] : face, f.off[0] ? nx[0][1] : f.x0, f.off[0] ? ny[0][1] : y1c};
  TexelAt t01{f.off[1] ? next_face[1] : face, f.off[1] ? nx[1][0] : f.x1, f.off[1] ? ny[1][0] : y0c};
  TexelAt t11{f.off[1] ? next_face[1] : face, f.off[1] ? nx[1][1] : f.x1, f.off[1] ? ny[1][1] : y1c};
  // Off in y but not in x: from the y neighbour.
  if (f.off[2] && !f.off[0]) t00 = {next_face[2], nx[2][0], ny[2][0]};
  if (f.off[2] && !f.off[1]) t01 = {next_face[2], nx[2][1], ny[2][1]};
  if (f.off[3] && !f.off[0]) t10 = {next_face[3], nx[3][0], ny[3][0]};
  if (f.off[3] && !f.off[1]) t11 = {next_face[3], nx[3][1], ny[3][1]};
  return {t00, t01, t10, t11};
}

const float* texel(const Level& level, int first_layer, const TexelAt& at) {
  const LevelSlice slice = level.slice(first_layer + at.face);
  return slice.texels + (std::size_t(at.y) * std::size_t(slice.width) + std::size_t(at.x)) * 4;
}

}  // namespace

CubeFace cube_face(float x, float y, float z, bool derivative_path) {
  const float dir[3] = {x, y, z};
  const Major m = major_axis(dir);
  CubeFace f;
  f.face = face_of(m);
  const float a = std::fabs(dir[m.axis]);
  const float scale = derivative_path ? std::fabs(0.5f * (1.0f / dir[m.axis])) : a > 0.0f ? 0.5f / a : 0.0f;
  face_coords(m, dir, f.s, f.t);
  f.s = f.s * scale + 0.5f;  // two roundings: a product, then a sum (no fused multiply-add)
  f.t = f.t * scale + 0.5f;
  return f;
}

CubeFace cube_face_with_derivatives(const float dir[3], const float dx[3], const float dy[3], float d[4]) {
  const Major m = major_axis(dir);
  const float ima = 1.0f / dir[m.axis];
  const float ima_half = 0.5f * ima;
  float sc, tc, sdx, tdx, sdy, tdy;
  face_coords(m, dir, sc, tc);
  face_coords(m, dx, sdx, tdx);
  face_coords(m, dy, sdy, tdy);
  const float ma_dx = dx[m.axis] * ima, ma_dy = dy[m.axis] * ima;
  d[0] = (sdx - ma_dx * sc) * ima_half;
  d[1] = (tdx - ma_dx * tc) * ima_half;
  d[2] = (sdy - ma_dy * sc) * ima_half;
  d[3] = (tdy - ma_dy * tc) * ima_half;
  return cube_face(dir[0], dir[1], dir[2], true);
}

bool cube_corner(int size, const CubeFace& at) { return footprint(size, at).corner(); }

void filter_cube_seamless(const Level& level, int first_layer, const CubeFace& at, FloatFilter filter,
                          const DepthCompare* compare, bool corner_in_vector, float out[4]) {
  const int size = level.width;
  Footprint f = footprint(size, at);
  if (filter == FloatFilter::NearestByWeights) {
    f.ws = f.ws > 0.5f ? 1.0f : 0.0f;
    f.wt = f.wt > 0.5f ? 1.0f : 0.0f;
  }
  const std::array<TexelAt, 4> at4 = footprint_texels(f, size, at.face);
  const float* t[4];  // x0 y0, x1 y0, x0 y1, x1 y1
  for (int k = 0; k < 4; ++k) t[k] = texel(level, first_layer, at4[std::size_t(k)]);
  bool pass[4] = {};
  if (compare)
    for (int k = 0; k < 4; ++k) pass[k] = passes(*compare, t[k][0]);
  if (!corner_in_vector) {  // interpolated as any 2D level (lp_build_lerp_2d, lp_build_masklerp2d)
    if (compare) {
      auto row = [&](int a, int b) { return (pass[b] ? f.ws : 0.0f) + (pass[a] ? 1.0f - f.ws : 0.0f); };
      out[0] = out[1] = out[2] = out[3] = lerp(f.wt, row(0, 1), row(2, 3));
      return;
    }
    for (int c = 0; c < 4; ++c) out[c] = lerp(f.wt, lerp(f.ws, t[0][c], t[1][c]), lerp(f.ws, t[2][c], t[3][c]));
    return;
  }
  // The weights, the corner's (if any) split in thirds among the other three.
  const float wx0 = 1.0f - f.ws, wy0 = 1.0f - f.wt;
  float w[4] = {wx0 * wy0, f.ws * wy0, wx0 * f.wt, f.ws * f.wt};
  float share = 0.0f;
  for (int k = 0; k < 4; ++k)
    if (f.missing(k)) share = w[k];
  share = share * (1.0f / 3.0f);
  for (int k = 0; k < 4; ++k) w[k] = f.missing(k) ? 0.0f : w[k] + share;
  if (compare) {
    float sum = pass[0] ? w[0] : 0.0f;
    for (int k = 1; k < 4; ++k) sum = (pass[k] ? w[k] : 0.0f) + sum;
    out[0] = out[1] = out[2] = out[3] = sum;
    return;
  }
  for (int c = 0; c < 4; ++c) {
    float sum = w[0] * t[0][c];
    for (int k = 1; k < 4; ++k) sum = w[k] * t[k][c] + sum;  // a product, then a sum
    out[c] = sum;
  }
}

void gather_cube_seamless(const Level& level, int first_layer, const CubeFace& at, int channel,
                          const DepthCompare* compare, bool average_corner, float out[4]) {
  const int size = level.width;
  const Footprint f = footprint(size, at);
  const std::array<TexelAt, 4> at4 = footprint_texels(f, size, at.face);
  float v[4];  // x0 y0, x1 y0, x0 y1, x1 y1
  for (int k = 0; k < 4; ++k) {
    const float* p = texel(level, first_layer, at4[std::size_t(k)]);
    v[k] = compare ? (passes(*compare, p[0]) ? 1.0f : 0.0f) : p[channel];
  }
  if (average_corner && f.corner()) {
    for (int k = 0; k < 4; ++k)
      if (f.missing(k)) v[k] = 0.0f;
    const float mean = (1.0f / 3.0f) * ((v[0] + v[1]) + (v[2] + v[3]));
    for (int k = 0; k < 4; ++k)
      if (f.missing(k)) v[k] = mean;
  }
  out[0] = v[2];  // i0 j1
  out[1] = v[3];  // i1 j1
  out[2] = v[1];  // i1 j0
  out[3] = v[0];  // i0 j0
}

}  // namespace tessref::texture
