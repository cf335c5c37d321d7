#include "texture/sample.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>

#include "common/fixed_point.h"
#include "texture/cube.h"
#include "texture/filter.h"
#include "texture/sampler_ops.h"

namespace tessref::texture {
namespace {

using namespace ops;

enum class Mip { None, Nearest, Linear };

Mip mip_mode(Filter f) {
  switch (f) {
    case Filter::NearestMipmapNearest: case Filter::LinearMipmapNearest: return Mip::Nearest;
    case Filter::NearestMipmapLinear: case Filter::LinearMipmapLinear: return Mip::Linear;
    default: return Mip::None;
  }
}
bool linear_image(Filter f) {
  return f == Filter::Linear || f == Filter::LinearMipmapNearest || f == Filter::LinearMipmapLinear;
}

// The mip filter as llvmpipe samples with it: none for a view of one level whose LOD range ends
// at 0 (level_zero_only).
Mip effective_mip(const Texture& t) {
  if (t.last_level == t.base_level && t.sampler.max_lod <= 0.0f) return Mip::None;
  return mip_mode(t.sampler.min_filter);
}

// Whether the sampler computes a LOD at all: for mipmaps, or to choose between minification and
// magnification filters that differ.
bool needs_lod(const SamplerState& s, Mip mip) {
  return mip != Mip::None || linear_image(s.min_filter) != linear_image(s.mag_filter);
}

// The levels a lookup reads and how: what llvmpipe's lp_build_lod_selector and its mip level
// functions compute.
struct LevelChoice {
  bool linear = false;  // the image filter: min or mag
  i32 level0 = 0, level1 = 0;
  float fpart = 0.0f;  // weight of level1 (mip LINEAR); 0: level0 alone
  // The second level llvmpipe filters when its vector blends two: level0 + 1, or level0 where
  // the LOD is clamped to the first or last level (level1 is level0 then when fpart is 0).
  i32 level1_filtered = 0;
};

// The sampler's LOD state as Gallium keeps it: GL_TEXTURE_MIN_LOD no lower than 0, the bias
// quantized to 1/256 within ±16 (util_quantize_lod_bias), and which clamps apply.
struct GalliumLod {
  float min_lod, max_lod, bias;
  bool min_max_equal, apply_min, apply_max;
};
GalliumLod gallium_lod(const SamplerState& s, bool needs_lod) {
  GalliumLod g;
  g.min_lod = s.min_lod > 0.0f ? s.min_lod : 0.0f;
  g.max_lod = s.max_lod;
  g.bias = std::round(std::clamp(s.lod_bias, -16.0f, 16.0f) * 256.0f) / 256.0f;
  g.min_max_equal = needs_lod && g.min_lod == g.max_lod;
  g.apply_min = needs_lod && !g.min_max_equal && g.min_lod > 0.0f;
  g.apply_max = needs_lod && !g.min_max_equal && g.max_lod < 15.0f;  // PIPE_MAX_TEXTURE_LEVELS - 1
  return g;
}

// ρ of a 1D texture (GL 4.6 equation 8.7 with v = 0): max(|ds/dx|, |ds/dy|) times the base
// level's width, as lp_build_rho computes it for one dimension (its exact form: no squares).
float rho_1d(const Texture& t, const LodInput& in) {
  float rho = max_ps(std::fabs(in.dsdx), std::fabs(in.dsdy)) * float(t.levels[std::size_t(t.base_level)].width);
  if (in.gradients && !std::isfinite(rho)) rho = 0.0f;
  return rho;
}

// ρ² of GL 4.6 equation 8.7 with the base level's size, each product and sum a float operation
// (lp_build_rho without the ρ approximation): the square root is folded into the log2 below.
// 1D textures: ρ_1d squared; 3D textures add (dr·d)² to each sum.
float rho_squared(const Texture& t, const LodInput& in) {
  if (dimensions(t.target) == 1) {
    const float rho = rho_1d(t, in);
    return rho * rho;
  }
  const Level& base = t.levels[std::size_t(t.base_level)];
  // A rectangle texture's too, though its coordinates are texels: Mesa's samplers (llvmpipe's and
  // softpipe's) scale them by its size as well, measured bit for bit.
  const float w = float(base.width), h = float(base.height);
  const float a = in.dsdx * w, b = in.dtdx * h, c = in.dsdy * w, d = in.dtdy * h;
  float rx = a * a + b * b, ry = c * c + d * d;
  if (t.target == Target::k3D) {
    const float depth = float(base.layers), e = in.drdx * depth, f = in.drdy * depth;
    rx = rx + e * e;
    ry = ry + f * f;
  }
  float rho2 = max_ps(rx, ry);
  if (in.gradients && !std::isfinite(rho2)) rho2 = 0.0f;
  return rho2;
}

// 0.5 * log2(ρ²) by lp_build_fast_log2: exponent plus mantissa - 1, exact at powers of two and
// linear between them (ρ = 1.5 gives 0.5625, not 0.585).
float half_fast_log2(float x) {
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(x);
  const i32 e = i32((bits >> 23) & 255u) - 127;
  const float m = std::bit_cast<float>((bits & 0x7fffffu) | 0x3f800000u);
  return (float(e - 1) + m) * 0.5f;
}

// The LOD after the shader's and the sampler's bias, before the clamps (textureQueryLod's .y),
// and after them. False for the shortcut: no bias, no clamp and a NEAREST or no mip filter give
// the level straight from ρ²'s exponent (lp_build_ilog2_sqrt), in `ipart` and `positive`.
struct LodValue {
  float unclamped = 0.0f, lod = 0.0f;
  bool shortcut = false;
  i32 ipart = 0;
  bool positive = false;
};
LodValue compute_lod(const Texture& t, const LodInput& in, Mip mip, const GalliumLod& g, bool query) {
  LodValue v;
  if (g.min_max_equal && !query) {
    v.unclamped = v.lod = g.min_lod;
    return v;
  }
  if (in.from == LodInput::From::Explicit) {
    v.lod = in.lod;
  } else {
    const float rho2 = rho_squared(t, in);
    if (!in.has_bias && !query && g.bias == 0.0f && !g.apply_max && !g.apply_min && mip != Mip::Linear) {
      v.shortcut = true;
      auto exponent = [](float x) { return i32((std::bit_cast<std::uint32_t>(x) >> 23) & 255u) - 127; };
      if (dimensions(t.target) == 1) {  // ρ itself: the exponent of ρ·√2 (lp_build_ilog2)
        const float rho = rho_1d(t, in);
        v.ipart = exponent(rho * std::numbers::sqrt2_v<float>);
        v.positive = rho > 1.0f;
      } else {  // ρ²: half its exponent, rounded up (lp_build_ilog2_sqrt)
        v.ipart = (exponent(rho2) + 1) >> 1;
        v.positive = rho2 > 1.0f;
      }
      return v;
    }
    v.lod = half_fast_log2(rho2);
    if (in.has_bias) v.lod = v.lod + in.bias;
  }
  if (g.bias != 0.0f) v.lod = v.lod + g.bias;
  v.unclamped = v.lod;
  if (g.apply_max) v.lod = min_ps(v.lod, g.max_lod);
  if (g.apply_min) v.lod = max_ps(v.lod, g.min_lod);
  return v;
}

LevelChoice choose_levels(const Texture& t, const LodInput& in) {
  const SamplerState& s = t.sampler;
  const Mip mip = effective_mip(t);
  const bool min_linear = linear_image(s.min_filter), mag_linear = linear_image(s.mag_filter);
  LevelChoice c;
  c.level0 = c.level1 = c.level1_filtered = t.base_level;
  if (!needs_lod(s, mip)) {
    c.linear = min_linear;
    return c;
  }
  const LodValue v = compute_lod(t, in, mip, gallium_lod(s, true), false);
  const bool positive = v.shortcut ? v.positive : v.lod > 0.0f;  // GL 4.6 8.15 with c = 0
  c.linear = positive ? min_linear : mag_linear;
  if (!positive || mip == Mip::None) return c;
  const i32 first = t.base_level, last = t.last_level;
  if (mip == Mip::Nearest) {
    const i32 ipart = v.shortcut ? v.ipart : iround(v.lod);
    c.level0 = c.level1 = c.level1_filtered = std::clamp(add(ipart, first), first, last);
    return c;
  }
  const float fl = std::floor(v.lod);
  i32 level0 = add(fptosi(fl), first);
  float fpart = v.lod - fl;
  c.level1_filtered = add(level0, 1);
  if (level0 < first) {
    level0 = c.level1_filtered = first;
    fpart = 0.0f;
  } else if (level0 >= last) {
    level0 = c.level1_filtered = last;
    fpart = 0.0f;
  }
  c.level0 = level0;
  c.level1 = fpart != 0.0f ? level0 + 1 : level0;
  c.fpart = fpart;
  return c;
}

// The wraps, and whether level 0's sides are powers of two. A seamless cube map's wraps are
// ignored (GL 4.6 8.14.2): clamped to the face's edge, whose neighbours are read where GL_LINEAR
// falls off it.
Axes axes_of(const Texture& t, bool seamless_cube) {
  const Level& level_zero = t.levels[0];
  const bool clamped = seamless_cube && is_cube(t.target);
  return {{clamped ? Wrap::ClampToEdge : t.sampler.wrap_s, clamped ? Wrap::ClampToEdge : t.sampler.wrap_t,
           t.sampler.wrap_r},
          {std::has_single_bit(unsigned(level_zero.width)), std::has_single_bit(unsigned(level_zero.height)),
           std::has_single_bit(unsigned(level_zero.layers))},
          dimensions(t.target), t.target != Target::kRectangle};
}

// The 8-bit fixed-point path (lp_build_sample_aos) serves formats of 8-bit unsigned normalized
// channels (not sRGB) with repeat or clamp-to-edge wraps, when the quad has one LOD or the
// minification and magnification filters agree; not a seamless cube map filtered with GL_LINEAR.
bool fixed_point_path(const Texture& t, const LodInput& in, bool seamless_cube) {
  const TexelFormatInfo& f = info(t.format);
  const SamplerState& s = t.sampler;
  if (seamless_cube && is_cube(t.target) && (linear_image(s.min_filter) || linear_image(s.mag_filter))) return false;
  auto simple = [](Wrap w) { return w == Wrap::Repeat || w == Wrap::ClampToEdge; };
  const Axes axes = axes_of(t, seamless_cube);
  return f.type == ChannelType::kUnorm8 && simple(axes.wrap[0]) && (axes.dims < 2 || simple(axes.wrap[1])) &&
         (axes.dims < 3 || simple(axes.wrap[2])) &&
         (in.per_quad || linear_image(s.min_filter) == linear_image(s.mag_filter));
}

// A cube map lookup's LOD input on its face: the derivatives of lod.cube_dir carried onto its face
// when llvmpipe computes a LOD from derivatives (for mipmaps or differing filters, unless the LOD
// range is one value), and ρ² then taken as from textureGrad's (infinite or NaN: 0). A query
// always carries them.
bool cube_derivatives(const Texture& t, const LodInput& in, bool query) {
  const SamplerState& s = t.sampler;
  const Mip mip = effective_mip(t);
  return in.from == LodInput::From::Derivatives &&
         (query || (needs_lod(s, mip) && !gallium_lod(s, true).min_max_equal));
}
LodInput lod_on_face(const Texture& t, const LodInput& in, bool query) {
  if (!cube_derivatives(t, in, query)) return in;
  const float dx[3] = {in.dsdx, in.dtdx, in.drdx}, dy[3] = {in.dsdy, in.dtdy, in.drdy};
  float d[4];
  cube_face_with_derivatives(in.cube_dir, dx, dy, d);
  LodInput out = in;
  out.dsdx = d[0];
  out.dtdx = d[1];
  out.dsdy = d[2];
  out.dtdy = d[3];
  out.drdx = out.drdy = 0.0f;
  out.gradients = true;
  return out;
}
// The face and coordinates on it of a cube map lookup at direction (at.s, at.t, at.r): by the
// derivative path's arithmetic when it is taken (the two differ in the scale's rounding).
CubeFace face_of_lookup(const Texture& t, const Coords& at, const LodInput& in) {
  return cube_face(at.s, at.t, at.r, cube_derivatives(t, in, false));
}

// 1 as format f's texels hold it: the integer 1 for integer formats.
float one(TexelFormat f) { return info(f).integer() ? integer_bits(1) : 1.0f; }

void apply_swizzle(const Texture& t, const float in[4], float out[4]) {
  for (int c = 0; c < 4; ++c) {
    switch (t.swizzle[std::size_t(c)]) {
      case Swizzle::Red: out[c] = in[0]; break;
      case Swizzle::Green: out[c] = in[1]; break;
      case Swizzle::Blue: out[c] = in[2]; break;
      case Swizzle::Alpha: out[c] = in[3]; break;
      case Swizzle::Zero: out[c] = 0.0f; break;
      case Swizzle::One: out[c] = one(t.format); break;
    }
  }
}

// GL 4.6 11.1.3.5: (0, 0, 0, 1), integers for an integer format. llvmpipe differs there
// (docs/textures.md): Mesa binds an RGBA8 texture in its place.
void incomplete(const Texture& t, float out[4]) {
  out[0] = out[1] = out[2] = 0.0f;
  out[3] = one(t.format);
}

// The comparison of a shadow lookup; D_ref clamped to [0, 1] for fixed-point depth formats (GL
// 4.6 8.23.1), as min(max(D_ref, 0), 1) with x86's min and max (NaN: 0).
std::optional<DepthCompare> depth_compare(const Texture& t, const float* dref) {
  if (!dref || !t.sampler.compare) return std::nullopt;
  const float ref = info(t.format).unsigned_normalized() ? min_ps(max_ps(*dref, 0.0f), 1.0f) : *dref;
  return DepthCompare{t.sampler.compare_func, ref};
}

}  // namespace

bool linear_in_vector(const Texture& t, const LodInput& lod_in, bool seamless_cube) {
  if (!t.complete) return false;
  const LodInput lod = is_cube(t.target) ? lod_on_face(t, lod_in, false) : lod_in;
  if (fixed_point_path(t, lod, seamless_cube)) return false;
  if (linear_image(t.sampler.min_filter) == linear_image(t.sampler.mag_filter)) return false;
  return choose_levels(t, lod).linear;
}

CubeCorners cube_corners(const Texture& t, const Coords& at, const LodInput& lod_in, const SampleContext& context) {
  CubeCorners r;
  if (!is_cube(t.target) || !context.seamless_cube || !t.complete) return r;
  const LodInput lod = lod_on_face(t, lod_in, false);
  if (fixed_point_path(t, lod, true)) return r;
  const LevelChoice c = choose_levels(t, lod);
  // GL_NEAREST lanes go through the linear filter too when their vector has a GL_LINEAR one.
  const bool differ = linear_image(t.sampler.min_filter) != linear_image(t.sampler.mag_filter);
  if (!c.linear && !(differ && context.vector_linear)) return r;
  const CubeFace face = face_of_lookup(t, at, lod_in);
  r.level[0] = cube_corner(t.levels[std::size_t(c.level0)].width, face);
  r.level[1] = cube_corner(t.levels[std::size_t(c.level1_filtered)].width, face);
  return r;
}

bool cube_lod_per_invocation(const Texture& t, bool has_bias) { return has_bias || effective_mip(t) != Mip::None; }

int array_layer(const Texture& t, float r) {
  if (!is_array(t.target) || !t.complete) return 0;
  const double layer = std::floor(double(r) + 0.5);  // exact: r + 0.5 in double
  const int last = t.levels[std::size_t(t.base_level)].layers / (is_cube(t.target) ? 6 : 1) - 1;
  return layer >= double(last) ? last : layer > 0.0 ? int(layer) : 0;  // NaN: 0
}

void sample(const Texture& t, const Coords& at_in, const LodInput& lod_in, const float* dref, float out[4],
            const SampleContext& context) {
  if (!t.complete) return incomplete(t, out);
  // A cube map is sampled on the face its direction points at, a layer of 6 per cube.
  const bool cube = is_cube(t.target);
  const CubeFace face = cube ? face_of_lookup(t, at_in, lod_in) : CubeFace{};
  const int first_face = 6 * at_in.layer;
  const Coords at = cube ? Coords{face.s, face.t, 0.0f, first_face + face.face} : at_in;
  const LodInput lod = cube ? lod_on_face(t, lod_in, false) : lod_in;
  const bool seamless = cube && context.seamless_cube;
  const LevelChoice c = choose_levels(t, lod);
  const Level& l0 = t.levels[std::size_t(c.level0)];
  const Axes axes = axes_of(t, seamless);
  const std::optional<DepthCompare> compare = depth_compare(t, dref);
  const DepthCompare* cmp = compare ? &*compare : nullptr;
  float texel[4];
  if (fixed_point_path(t, lod, seamless)) {
    std::uint8_t r0[4];
    filter_level_unorm8(t.format, t.target == Target::k3D, l0, axes, c.linear, at, r0);
    // The levels' weight in 8 bits, truncated (lp_build_sample_mipmap's lod_fpart.fixed16).
    const i32 w = fptosi(c.fpart * 256.0f);
    if (w > 0) {
      std::uint8_t r1[4];
      filter_level_unorm8(t.format, t.target == Target::k3D, t.levels[std::size_t(c.level1)], axes, c.linear, at, r1);
      for (int k = 0; k < 4; ++k) r0[k] = fixed::unorm8_lerp(w, r0[k], r1[k]);
    }
    for (int k = 0; k < 4; ++k) texel[k] = fixed::unorm8_texel_to_float(r0[k]);
  } else {
    const std::array<float, 4> border = border_color(t);
    const FloatFilter filter =
        c.linear ? FloatFilter::Linear
        : context.vector_linear && linear_image(t.sampler.min_filter) != linear_image(t.sampler.mag_filter)
            ? FloatFilter::NearestByWeights
            : FloatFilter::Nearest;
    // The first (k = 0) or second level.
    auto filter_level = [&](int k, const Level& level, float result[4]) {
      if (seamless && filter != FloatFilter::Nearest)
        filter_cube_seamless(level, first_face, face, filter, cmp, context.vector_corner[k], result);
      else
        filter_level_float(t.target == Target::k3D, level, axes, border, filter, at, cmp, result);
    };
    filter_level(0, l0, texel);
    if (c.fpart > 0.0f) {
      float t1[4];
      filter_level(1, t.levels[std::size_t(c.level1)], t1);
      for (int k = 0; k < 4; ++k) texel[k] = lerp(c.fpart, texel[k], t1[k]);
    }
  }
  if (cmp) {  // the swizzle is refused with a comparison (scene/texture_schema.cpp)
    for (int k = 0; k < 4; ++k) out[k] = texel[k];
    return;
  }
  apply_swizzle(t, texel, out);
}

void gather(const Texture& t, const Coords& at, int component, const float* dref, bool seamless_cube, float out[4]) {
  const Swizzle sw = t.swizzle[std::size_t(component & 3)];
  if (!t.complete) {  // the four texels of the 1 x 1 (0, 0, 0, 1) texture
    float texel[4], swizzled[4];
    incomplete(t, texel);
    apply_swizzle(t, texel, swizzled);
    out[0] = out[1] = out[2] = out[3] = swizzled[component & 3];
    return;
  }
  const std::optional<DepthCompare> compare = depth_compare(t, dref);
  if (!compare && (sw == Swizzle::Zero || sw == Swizzle::One)) {
    out[0] = out[1] = out[2] = out[3] = sw == Swizzle::One ? one(t.format) : 0.0f;
    return;
  }
  // GL_LINEAR's footprint on the base level whatever the filters (llvmpipe: linear, no mipmap).
  const Level& base = t.levels[std::size_t(t.base_level)];
  const DepthCompare* cmp = compare ? &*compare : nullptr;
  if (is_cube(t.target)) {  // on the face the direction points at; no offsets
    const CubeFace face = cube_face(at.s, at.t, at.r);
    if (seamless_cube)
      gather_cube_seamless(base, 6 * at.layer, face, int(sw), cmp, !info(t.format).integer(), out);
    else
      gather_float(base.slice(6 * at.layer + face.face), axes_of(t, false), border_color(t), face.s, face.t, 0, 0, int(sw),
                   cmp, out);
    return;
  }
  gather_float(base.slice(at.layer), axes_of(t, false), border_color(t), at.s, at.t, at.offset_s, at.offset_t, int(sw), cmp,
               out);
}

void fetch(const Texture& t, int i, int j, int layer, int lod, float out[4]) {
  if (!t.complete) return incomplete(t, out);
  const std::int64_t level = std::int64_t(t.base_level) + lod;
  // Outside: zero in each channel the format has; the others read 0 (green, blue) and 1 (alpha).
  float texel[4] = {0.0f, 0.0f, 0.0f, info(t.format).channels < 4 ? one(t.format) : 0.0f};
  if (level >= t.base_level && level <= t.last_level) {
    const Level& l = t.levels[std::size_t(level)];
    if (i >= 0 && j >= 0 && i < l.width && j < l.height && layer >= 0 && layer < l.layers) {
      const LevelSlice slice = l.slice(layer);
      for (int c = 0; c < 4; ++c) texel[c] = slice.texels[(std::size_t(j) * std::size_t(l.width) + std::size_t(i)) * 4 + std::size_t(c)];
    }
  }
  apply_swizzle(t, texel, out);
}

void level_size(const Texture& t, int lod, int out[3]) {
  if (!t.complete) {
    out[0] = out[1] = out[2] = 1;
    return;
  }
  const std::int64_t level = t.target == Target::kBuffer ? 0 : std::int64_t(t.base_level) + lod;
  out[0] = out[1] = out[2] = 0;
  if (level < t.base_level || level > t.last_level) return;
  const Level& l = t.levels[std::size_t(level)];
  int k = 0;
  out[k++] = l.width;
  if (dimensions(t.target) >= 2) out[k++] = l.height;
  if (is_array(t.target) || t.target == Target::k3D) out[k++] = is_cube(t.target) ? l.layers / 6 : l.layers;
}

int query_levels(const Texture& t) { return t.complete ? t.last_level - t.base_level + 1 : 1; }

void query_lod(const Texture& t, const LodInput& lod_in, float out[2]) {
  if (!t.complete) {
    out[0] = out[1] = 0.0f;
    return;
  }
  const LodInput in = is_cube(t.target) ? lod_on_face(t, lod_in, true) : lod_in;
  const Mip mip = mip_mode(t.sampler.min_filter);
  const LodValue v = compute_lod(t, in, mip, gallium_lod(t.sampler, needs_lod(t.sampler, mip)), true);
  float level = 0.0f;
  const float top = float(t.last_level - t.base_level);
  if (mip == Mip::Nearest) level = min_ps(max_ps(std::nearbyint(v.lod), 0.0f), top);
  if (mip == Mip::Linear) level = min_ps(max_ps(v.lod, 0.0f), top);
  out[0] = level;
  out[1] = v.unclamped;
}

}  // namespace tessref::texture
