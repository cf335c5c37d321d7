#include "texture/filter.h"

#include <algorithm>
#include <cmath>

#include "common/fixed_point.h"
#include "texture/sampler_ops.h"

namespace tessref::texture {
namespace {

using namespace ops;

// GL's mirror function by llvmpipe's lp_build_coord_mirror: 2 * (c/2 - round(c/2)), its absolute
// value, NaN to 0.
float mirror(float c) {
  const float h = c * 0.5f;
  const float f = h - std::nearbyint(h);
  return max_ps(std::fabs(f + f), 0.0f);
}

// The fraction of c, at most the float just below 1 (NaN: that float).
float fract_safe(float c) { return min_ps(c - std::floor(c), 0x1.fffffep-1f); }

// GL_NEAREST: the texel index along one axis of a level `w` texels long; -1 for the border colour
// (lp_build_sample_wrap_nearest).
i32 nearest_index(float s, i32 w, i32 off, Wrap wrap, bool pot, bool normalized = true) {
  const float wf = float(w);
  const float scale = normalized ? wf : 1.0f;  // a rectangle texture's coordinates are texels
  i32 i = 0;
  switch (wrap) {
    case Wrap::Repeat:
      if (pot) return add(ifloor(s * wf), off) & (w - 1);
      if (off) s = s + float(off) / wf;
      i = fptosi(fract_safe(s) * wf);
      break;
    case Wrap::ClampToEdge: {
      float c = s * scale;
      if (off) c = c + float(off);
      i = std::clamp(fptosi(c), 0, w - 1);
      break;
    }
    case Wrap::ClampToBorder:
      i = add(ifloor(s * scale), off);
      return i < 0 || i >= w ? -1 : i;
    case Wrap::MirroredRepeat:
      if (off) s = s + float(off) / wf;
      i = std::min(fptosi(mirror(s) * wf), w - 1);
      break;
    case Wrap::MirrorClampToEdge: {
      float c = s * scale;
      if (off) c = c + float(off);
      i = i32(std::min(std::uint32_t(fptosi(std::fabs(c))), std::uint32_t(w - 1)));  // unsigned min
      break;
    }
  }
  return std::clamp(i, 0, w - 1);
}

// GL_LINEAR in float: the two texel indices (-1 for the border) and the weight of the second
// (lp_build_sample_wrap_linear).
struct LinearIndices {
  i32 i0, i1;
  float weight;
};
LinearIndices linear_indices(float s, i32 w, i32 off, Wrap wrap, bool pot, bool normalized = true) {
  const float wf = float(w);
  const float scale = normalized ? wf : 1.0f;
  auto floor_fract = [](float c, i32& i, float& f) {
    const float fl = std::floor(c);
    i = fptosi(fl);
    f = c - fl;
  };
  LinearIndices r{0, 0, 0.0f};
  switch (wrap) {
    case Wrap::Repeat:
      if (pot) {
        float c = s * wf - 0.5f;
        if (off) c = c + float(off);
        floor_fract(c, r.i0, r.weight);
        r.i1 = add(r.i0, 1) & (w - 1);
        r.i0 &= w - 1;
      } else {
        if (off) s = s + float(off) / wf;
        const float c = (s - std::floor(s)) * wf - 0.5f;
        const bool negative = !(c >= 0.0f);  // unordered: NaN counts
        floor_fract(c, r.i0, r.weight);
        if (negative) r.i0 = w - 1;
        r.i1 = r.i0 != w - 1 ? add(r.i0, 1) : 0;
      }
      break;
    case Wrap::ClampToEdge: {
      float c = s * scale;
      if (off) c = c + float(off);
      c = max_ps(min_ps(c, wf) - 0.5f, 0.0f);  // NaN: w - 0.5
      floor_fract(c, r.i0, r.weight);
      r.i1 = std::min(add(r.i0, 1), w - 1);
      break;
    }
    case Wrap::ClampToBorder: {
      float c = s * scale;
      if (off) c = c + float(off);
      floor_fract(c - 0.5f, r.i0, r.weight);
      r.i1 = add(r.i0, 1);
      if (r.i0 < 0 || r.i0 >= w) r.i0 = -1;
      if (r.i1 < 0 || r.i1 >= w) r.i1 = -1;
      return r;
    }
    case Wrap::MirroredRepeat: {
      if (off) s = s + float(off) / wf;
      floor_fract(mirror(s) * wf - 0.5f, r.i0, r.weight);
      r.i1 = std::min(add(r.i0, 1), w - 1);
      r.i0 = std::max(r.i0, 0);
      break;
    }
    case Wrap::MirrorClampToEdge: {
      float c = s * scale;
      if (off) c = c + float(off);
      c = max_ps(min_ps(std::fabs(c), wf) - 0.5f, 0.0f);
      floor_fract(c, r.i0, r.weight);
      r.i1 = std::min(add(r.i0, 1), w - 1);
      break;
    }
  }
  r.i0 = std::clamp(r.i0, 0, w - 1);
  r.i1 = std::clamp(r.i1, 0, w - 1);
  return r;
}

// textureGather's two texel indices along one axis (-1 for the border): GL_LINEAR's, but where
// llvmpipe's linear selection relies on the weight (a pair swapped in a mirrored section, or
// indices 0 and 1 with weight 0 next to an edge), its gather path takes the texels GL names
// (lp_build_sample_wrap_linear with is_gather).
std::array<i32, 2> gather_indices(float s, i32 w, i32 off, Wrap wrap, bool pot, bool normalized) {
  const float wf = float(w);
  const float scale = normalized ? wf : 1.0f;
  // Ones' complement for negative indices: mirror(-x) = x - 1.
  auto mirrored = [w](i32 i) { return std::min(i < 0 ? ~i : i, w - 1); };
  switch (wrap) {
    case Wrap::ClampToEdge: {
      float c = s * scale;
      if (off) c = c + float(off);
      c = max_ps(min_ps(c, wf), 0.0f);  // NaN: w
      return {fptosi(c - 0.5f), std::min(fptosi(c + 0.5f), w - 1)};
    }
    case Wrap::MirroredRepeat: {
      if (off) s = s + float(off) / wf;
      const float h = s * 0.5f;
      const float f = h - std::nearbyint(h);
      const i32 i0 = ifloor((f + f) * wf - 0.5f);  // the mirror's sign kept: negative in odd sections
      return {mirrored(i0), mirrored(add(i0, 1))};
    }
    case Wrap::MirrorClampToEdge: {
      float c = s * scale;
      if (off) c = c + float(off);
      const i32 i0 = ifloor(c - 0.5f);
      return {mirrored(i0), mirrored(add(i0, 1))};
    }
    default: {
      const LinearIndices r = linear_indices(s, w, off, wrap, pot, normalized);
      return {r.i0, r.i1};
    }
  }
}

// GL_LINEAR in 8-bit fixed point: the coordinate in 1/256 texels, rounded (ties to even), less
// half a texel; its integer part and 8-bit weight (lp_build_sample_image_linear, AoS).
struct LinearIndices8 {
  i32 i0, i1, weight;
};
LinearIndices8 linear_indices8(float s, i32 w, i32 off, Wrap wrap, bool pot, bool normalized = true) {
  const i32 u = add(iround(s * (normalized ? float(w * 256) : 256.0f)), -128);
  LinearIndices8 r{add(u >> 8, off), 0, u & 255};
  if (wrap == Wrap::ClampToEdge) {
    r.i1 = std::clamp(add(r.i0, 1), 0, w - 1);
    r.i0 = std::clamp(r.i0, 0, w - 1);
  } else if (pot) {
    r.i1 = add(r.i0, 1) & (w - 1);
    r.i0 &= w - 1;
  } else {
    // lp_build_coord_repeat_npot_linear_int: from the coordinate's fraction.
    if (off) s = s + float(off) / float(w);
    const i32 v = add(iround((s - std::floor(s)) * float(w) * 256.0f), -128);
    r.weight = v & 255;
    r.i0 = v >> 8;
    if (r.i0 < 0) r.i0 = w - 1;
    r.i0 = std::min(r.i0, w - 1);
    r.i1 = r.i0 != w - 1 ? r.i0 + 1 : 0;
  }
  r.i0 = std::clamp(r.i0, 0, w - 1);
  r.i1 = std::clamp(r.i1, 0, w - 1);
  return r;
}

i32 nearest_index8(float s, i32 w, i32 off, Wrap wrap, bool pot, bool normalized = true) {
  if (wrap == Wrap::Repeat && !pot) return nearest_index(s, w, off, wrap, pot);
  const i32 i = add(ifloor(normalized ? s * float(w) : s), off);
  return wrap == Wrap::Repeat ? i & (w - 1) : std::clamp(i, 0, w - 1);
}

void texel8(TexelFormat format, const LevelSlice& l, i32 i, i32 j, std::uint8_t out[4]) {
  const int channels = info(format).channels;
  const std::uint8_t* p = l.stored + (std::size_t(j) * std::size_t(l.width) + std::size_t(i)) * std::size_t(channels);
  for (int c = 0; c < 4; ++c) out[c] = c < channels ? p[c] : c == 3 ? 255 : 0;
}

void texelf(const LevelSlice& l, const std::array<float, 4>& border, i32 i, i32 j, float out[4]) {
  if (i < 0 || j < 0) {
    for (int c = 0; c < 4; ++c) out[c] = border[std::size_t(c)];
    return;
  }
  const float* p = l.texels + (std::size_t(j) * std::size_t(l.width) + std::size_t(i)) * 4;
  for (int c = 0; c < 4; ++c) out[c] = p[c];
}

// Along one axis of `size` texels (a 3D texture's r): the texels a lookup reads, -1 for the
// border colour, and the second one's weight. GL_NEAREST reads k0 alone; GL_LINEAR in float gives
// `weight`, on the 8-bit path `weight8` (in 256ths), as for s and t.
struct AxisTexels {
  i32 k0 = 0, k1 = 0;
  float weight = 0.0f;
  i32 weight8 = 0;
};
AxisTexels axis_texels(float c, int size, int offset, Wrap wrap, bool pot, bool linear, bool unorm8) {
  AxisTexels a;
  if (!linear) {
    a.k0 = a.k1 = unorm8 ? nearest_index8(c, size, offset, wrap, pot) : nearest_index(c, size, offset, wrap, pot);
  } else if (unorm8) {
    const LinearIndices8 l = linear_indices8(c, size, offset, wrap, pot);
    a = {l.i0, l.i1, 0.0f, l.weight};
  } else {
    const LinearIndices l = linear_indices(c, size, offset, wrap, pot);
    a = {l.i0, l.i1, l.weight, 0};
  }
  return a;
}

}  // namespace

void filter_unorm8(TexelFormat format, const LevelSlice& level, const Axes& axes, bool linear, float s, float t,
                   int offset_s, int offset_t, std::uint8_t out[4]) {
  const i32 w = level.width, h = level.height;
  const bool one_d = axes.dims == 1;
  if (!linear) {
    texel8(format, level, nearest_index8(s, w, offset_s, axes.wrap[0], axes.pot[0], axes.normalized),
           one_d ? 0 : nearest_index8(t, h, offset_t, axes.wrap[1], axes.pot[1], axes.normalized), out);
    return;
  }
  const LinearIndices8 x = linear_indices8(s, w, offset_s, axes.wrap[0], axes.pot[0], axes.normalized);
  std::uint8_t t00[4], t10[4], t01[4], t11[4];
  if (one_d) {
    texel8(format, level, x.i0, 0, t00);
    texel8(format, level, x.i1, 0, t10);
    for (int c = 0; c < 4; ++c) out[c] = fixed::unorm8_lerp(x.weight, t00[c], t10[c]);
    return;
  }
  const LinearIndices8 y = linear_indices8(t, h, offset_t, axes.wrap[1], axes.pot[1], axes.normalized);
  texel8(format, level, x.i0, y.i0, t00);
  texel8(format, level, x.i1, y.i0, t10);
  texel8(format, level, x.i0, y.i1, t01);
  texel8(format, level, x.i1, y.i1, t11);
  for (int c = 0; c < 4; ++c)
    out[c] = fixed::unorm8_lerp(y.weight, fixed::unorm8_lerp(x.weight, t00[c], t10[c]),
                                fixed::unorm8_lerp(x.weight, t01[c], t11[c]));
}

bool passes(const DepthCompare& c, float depth) {
  const float r = c.ref;
  switch (c.func) {
    case CompareFunc::Never: return false;
    case CompareFunc::Less: return r < depth;
    case CompareFunc::Equal: return r == depth;
    case CompareFunc::Lequal: return r <= depth;
    case CompareFunc::Greater: return r > depth;
    case CompareFunc::Notequal: return !(r == depth);
    case CompareFunc::Gequal: return r >= depth;
    case CompareFunc::Always: return true;
  }
  return false;
}

void filter_float(const LevelSlice& level, const Axes& axes, const std::array<float, 4>& border, FloatFilter filter,
                  float s, float t, int offset_s, int offset_t, const DepthCompare* compare, float out[4]) {
  const i32 w = level.width, h = level.height;
  const bool one_d = axes.dims == 1;
  if (filter == FloatFilter::Nearest) {
    const i32 i = nearest_index(s, w, offset_s, axes.wrap[0], axes.pot[0], axes.normalized);
    const i32 j = one_d ? 0 : nearest_index(t, h, offset_t, axes.wrap[1], axes.pot[1], axes.normalized);
    texelf(level, border, i, j, out);
    if (compare) out[0] = out[1] = out[2] = out[3] = passes(*compare, out[0]) ? 1.0f : 0.0f;
    return;
  }
  LinearIndices x = linear_indices(s, w, offset_s, axes.wrap[0], axes.pot[0], axes.normalized);
  LinearIndices y = one_d ? LinearIndices{0, 0, 0.0f} : linear_indices(t, h, offset_t, axes.wrap[1], axes.pot[1], axes.normalized);
  if (filter == FloatFilter::NearestByWeights) {
    x.weight = x.weight > 0.5f ? 1.0f : 0.0f;
    y.weight = y.weight > 0.5f ? 1.0f : 0.0f;
  }
  float t00[4], t10[4], t01[4], t11[4];
  texelf(level, border, x.i0, y.i0, t00);
  texelf(level, border, x.i1, y.i0, t10);
  // lp_build_masklerp: the weights selected by the tests and added.
  const float wx1 = 1.0f - x.weight;
  auto row = [&](const float* a, const float* b) {
    return (passes(*compare, b[0]) ? x.weight : 0.0f) + (passes(*compare, a[0]) ? wx1 : 0.0f);
  };
  if (one_d) {  // one interpolation, along s
    if (compare) out[0] = out[1] = out[2] = out[3] = row(t00, t10);
    else
      for (int c = 0; c < 4; ++c) out[c] = lerp(x.weight, t00[c], t10[c]);
    return;
  }
  texelf(level, border, x.i0, y.i1, t01);
  texelf(level, border, x.i1, y.i1, t11);
  if (compare) {
    out[0] = out[1] = out[2] = out[3] = lerp(y.weight, row(t00, t10), row(t01, t11));
    return;
  }
  for (int c = 0; c < 4; ++c)
    out[c] = lerp(y.weight, lerp(x.weight, t00[c], t10[c]), lerp(x.weight, t01[c], t11[c]));
}

void gather_float(const LevelSlice& level, const Axes& axes, const std::array<float, 4>& border, float s, float t,
                  int offset_s, int offset_t, int channel, const DepthCompare* compare, float out[4]) {
  const std::array<i32, 2> x = gather_indices(s, level.width, offset_s, axes.wrap[0], axes.pot[0], axes.normalized);
  const std::array<i32, 2> y = gather_indices(t, level.height, offset_t, axes.wrap[1], axes.pot[1], axes.normalized);
  const i32 corners[4][2] = {{x[0], y[1]}, {x[1], y[1]}, {x[1], y[0]}, {x[0], y[0]}};
  for (int k = 0; k < 4; ++k) {
    float texel[4];
    texelf(level, border, corners[k][0], corners[k][1], texel);
    out[k] = compare ? (passes(*compare, texel[0]) ? 1.0f : 0.0f) : texel[channel];
  }
}

void filter_level_unorm8(TexelFormat format, bool three_d, const Level& level, const Axes& axes, bool linear,
                         const Coords& at, std::uint8_t out[4]) {
  if (!three_d) {
    filter_unorm8(format, level.slice(at.layer), axes, linear, at.s, at.t, at.offset_s, at.offset_t, out);
    return;
  }
  const AxisTexels r = axis_texels(at.r, level.layers, at.offset_r, axes.wrap[2], axes.pot[2], linear, true);
  filter_unorm8(format, level.slice(r.k0), axes, linear, at.s, at.t, at.offset_s, at.offset_t, out);
  if (!linear) return;
  std::uint8_t second[4];
  filter_unorm8(format, level.slice(r.k1), axes, linear, at.s, at.t, at.offset_s, at.offset_t, second);
  for (int c = 0; c < 4; ++c) out[c] = fixed::unorm8_lerp(r.weight8, out[c], second[c]);
}

void filter_level_float(bool three_d, const Level& level, const Axes& axes, const std::array<float, 4>& border,
                        FloatFilter filter, const Coords& at, const DepthCompare* compare, float out[4]) {
  if (!three_d) {
    filter_float(level.slice(at.layer), axes, border, filter, at.s, at.t, at.offset_s, at.offset_t, compare, out);
    return;
  }
  const bool linear = filter != FloatFilter::Nearest;
  AxisTexels r = axis_texels(at.r, level.layers, at.offset_r, axes.wrap[2], axes.pot[2], linear, false);
  if (filter == FloatFilter::NearestByWeights) r.weight = r.weight > 0.5f ? 1.0f : 0.0f;
  auto slice = [&](i32 k, float texel[4]) {
    if (k < 0) {
      for (int c = 0; c < 4; ++c) texel[c] = border[std::size_t(c)];
      return;
    }
    filter_float(level.slice(k), axes, border, filter, at.s, at.t, at.offset_s, at.offset_t, compare, texel);
  };
  slice(r.k0, out);
  if (!linear) return;
  float second[4];
  slice(r.k1, second);
  for (int c = 0; c < 4; ++c) out[c] = lerp(r.weight, out[c], second[c]);
}

std::array<float, 4> border_color(const Texture& t) {
  const TexelFormatInfo& f = info(t.format);
  if (f.integer()) {
    // Clamped to the range of the format's first channel, but 32-bit channels are kept as
    // they are and GL_RGB10_A2UI's are clamped per channel (lp_build_clamp_border_color).
    const bool per_channel = f.type == ChannelType::kUint10_10_10_2;
    std::array<float, 4> b;
    for (int c = 0; c < 4; ++c) {
      const int range = per_channel ? c : 0;  // whose range clamps channel c
      const std::int64_t v = c < f.channels ? std::clamp(t.sampler.border_integer[std::size_t(c)], f.integer_min(range),
                                                         f.integer_max(range))
                                            : c == 3 ? 1 : 0;
      b[std::size_t(c)] = integer_bits(v);
    }
    return b;
  }
  std::array<float, 4> b = t.sampler.border;
  // Clamped to the format's range (lp_build_clamp_border_color: x86's max then min, NaN to the
  // bound).
  float lo = -INFINITY, hi = INFINITY;
  if (f.unsigned_normalized()) lo = 0.0f, hi = 1.0f;
  if (f.signed_normalized()) lo = -1.0f, hi = 1.0f;
  if (f.type == ChannelType::kUfloat11_11_10) lo = 0.0f;
  if (f.type == ChannelType::kRgb9E5) lo = 0.0f, hi = kMaxRgb9E5;
  for (float& c : b) {
    if (lo != -INFINITY) c = max_ps(c, lo);
    if (hi != INFINITY) c = min_ps(c, hi);
  }
  // Read through the format, as a texel is: channels it lacks are 0 (green, blue) and 1 (alpha).
  for (int c = f.channels; c < 4; ++c) b[std::size_t(c)] = c == 3 ? 1.0f : 0.0f;
  return b;
}

}  // namespace tessref::texture
