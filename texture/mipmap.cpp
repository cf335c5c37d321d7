#include "texture/mipmap.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "common/fixed_point.h"
#include "common/srgb.h"
#include "texture/filter.h"

namespace tessref::texture {
namespace {

// The value llvmpipe stores for x in a render target channel of this type, as a float that the
// format encodes exactly: 8 bits rounded, sRGB encoded, a half rounded toward zero
// (common/fixed_point.h); 16 bits as lp_build_clamped_float_to_unsigned_norm does it (x times the
// float nearest 65535/65536, plus 128: the low 16 bits of the sum's significand, rounded to
// nearest even); signed normalized as round(min(x, 1) * (2^(b-1) - 1)) in float; the 11- and
// 10-bit floats truncated (lp_build_float_to_smallfloat rounds toward zero). GL_RGB9_E5 is not a
// render target: Mesa generates its levels on the CPU with GL's shared-exponent equations, which
// the format's own encoding is.
float render_target_value(ChannelType type, int channel, float x) {
  switch (type) {
    case ChannelType::kFloat16: return fixed::half_round_toward_zero(x);
    case ChannelType::kSrgb8: return channel < 3 ? fixed::unorm8_to_float(srgb_encode(x)) : x;
    case ChannelType::kUnorm16: {
      const float sum = x * static_cast<float>(65535.0 / 65536.0) + 128.0f;
      return float(std::bit_cast<std::uint32_t>(sum) & 0xffffu) / 65535.0f;
    }
    case ChannelType::kSnorm8: case ChannelType::kSnorm16: {
      const float scale = type == ChannelType::kSnorm8 ? 127.0f : 32767.0f;
      const float k = std::clamp(std::nearbyint((x < 1.0f ? x : 1.0f) * scale), -scale - 1.0f, scale);
      return k / scale;
    }
    case ChannelType::kUfloat11_11_10: {
      if (!(x > 0.0f) || std::isinf(x)) return x > 0.0f ? x : 0.0f;
      const int m = channel < 2 ? 6 : 5;
      int e = 0;
      std::frexp(double(x), &e);
      const int exponent = std::max(e - 1, -14);  // denormals: the exponent of 2^-14
      return float(std::ldexp(std::floor(std::ldexp(double(x), m - exponent)), exponent - m));
    }
    default: return x;
  }
}

// A plane a0 + x·dadx + y·dady through three vertices (x, y, a), as llvmpipe's setup computes it
// (lp_state_setup.c: calc_coef4, with the pixel centre at x0 - 0.5), each step one float
// operation.
struct Plane {
  float a0, dadx, dady;
};
Plane setup_plane(const float (&v)[3][3]) {
  const float dx01 = v[0][0] - v[1][0], dy01 = v[0][1] - v[1][1];
  const float dx20 = v[2][0] - v[0][0], dy20 = v[2][1] - v[0][1];
  const float ooa = 1.0f / (dx01 * dy20 - dy01 * dx20);
  const float dy20_ooa = dy20 * ooa, dy01_ooa = dy01 * ooa, dx20_ooa = dx20 * ooa, dx01_ooa = dx01 * ooa;
  const float da01 = v[0][2] - v[1][2], da20 = v[2][2] - v[0][2];
  const float dadx = da01 * dy20_ooa - da20 * dy01_ooa;
  const float dady = da20 * dx01_ooa - da01 * dx20_ooa;
  const float x0 = v[0][0] - 0.5f, y0 = v[0][1] - 0.5f;
  return {v[0][2] - (dadx * x0 + dady * y0), dadx, dady};
}

// Where llvmpipe's blit samples level k for texel (x, y) of level k + 1, w x h: u_blitter draws the
// level as a rectangle from (0, 0) to (w, h) with coordinates 0 to 1 across, a fan that Mesa's draw
// module splits into the triangles (v1, v2, v0) and (v2, v3, v0); each one's planes are
// interpolated at the pixel by two fused multiply-adds (lp_bld_interp.c), and a pixel centre on
// the diagonal belongs to the first. Exactly the texel centre (x + 0.5) / w only where that is a
// dyadic number (power-of-two sizes); elsewhere a few ulps off it, measured bit for bit against
// llvmpipe's levels on 807 texels of 11 sizes.
class BlitCoordinates {
 public:
  BlitCoordinates(int w, int h) : w_(w), h_(h) {
    const float fw = float(w), fh = float(h);
    const float corners[4][2] = {{0.0f, 0.0f}, {fw, 0.0f}, {fw, fh}, {0.0f, fh}};
    const float st[4][2] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};
    const int triangles[2][3] = {{1, 2, 0}, {2, 3, 0}};
    for (int k = 0; k < 2; ++k)
      for (int c = 0; c < 2; ++c) {
        float v[3][3];
        for (int i = 0; i < 3; ++i) {
          const int at = triangles[k][i];
          v[i][0] = corners[at][0], v[i][1] = corners[at][1], v[i][2] = st[at][c];
        }
        planes_[k][c] = setup_plane(v);
      }
  }
  // (s, t) at texel (x, y).
  std::array<float, 2> at(int x, int y) const {
    // Above the diagonal from (0, 0) to (w, h): (y + 1/2) w > (x + 1/2) h, in integers.
    const int k = std::int64_t(2 * y + 1) * w_ > std::int64_t(2 * x + 1) * h_ ? 1 : 0;
    std::array<float, 2> out;
    for (int c = 0; c < 2; ++c) {
      const Plane& p = planes_[k][c];
      out[std::size_t(c)] = std::fma(p.dady, float(y), std::fma(p.dadx, float(x), p.a0));
    }
    return out;
  }

 private:
  int w_, h_;
  Plane planes_[2][2];
};

// Level k + 1 from level k as Mesa makes it on llvmpipe (util_gen_mipmap): a blit of level k into
// level k + 1 that samples level k with GL_LINEAR and GL_CLAMP_TO_EDGE at each new texel's
// centre (BlitCoordinates), through the same sampler as any lookup (8-bit fixed point for 8-bit
// normalized formats, float otherwise), then stores the result as llvmpipe's render target of the
// format stores it (render_target_value). For an even size that is the mean of a 2 x 2 block; an
// odd size weighs two texels at the centre, not three. GL_RGB9_E5, no render target, is averaged
// on the CPU at the exact centres.
// An array's layers are blitted one by one; a 3D texture's new slice z samples its two nearest
// slices at r = (z + 0.5) / depth, each as a 2D level, and interpolates them (as lerp_3d does).
Level downsample(TexelFormat format, Target target, const Level& src, int w, int h) {
  const Axes clamp{{Wrap::ClampToEdge, Wrap::ClampToEdge, Wrap::ClampToEdge}, {false, false, false}, dimensions(target)};
  const std::array<float, 4> no_border{};
  const ChannelType type = info(format).type;
  const bool unorm8 = type == ChannelType::kUnorm8, three_d = target == Target::k3D;
  const int layers = three_d ? std::max(1, src.layers / 2) : src.layers;
  std::vector<float> rgba(std::size_t(w) * std::size_t(h) * std::size_t(layers) * 4);
  const BlitCoordinates blit(w, h);
  for (int layer = 0; layer < layers; ++layer) {
    float* to = rgba.data() + std::size_t(layer) * std::size_t(w) * std::size_t(h) * 4;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        // An array's layer is itself; a 3D texture's new slice samples r at its centre.
        std::array<float, 2> st = blit.at(x, y);
        if (type == ChannelType::kRgb9E5) st = {(float(x) + 0.5f) / float(w), (float(y) + 0.5f) / float(h)};
        const Coords at{st[0], st[1], three_d ? (float(layer) + 0.5f) / float(layers) : 0.0f, three_d ? 0 : layer};
        float* out = to + (std::size_t(y) * std::size_t(w) + std::size_t(x)) * 4;
        if (unorm8) {
          std::uint8_t texel[4];
          filter_level_unorm8(format, three_d, src, clamp, true, at, texel);
          for (int c = 0; c < 4; ++c) out[c] = fixed::unorm8_to_float(texel[c]);  // exact k / 255: encodes to k
          continue;
        }
        filter_level_float(three_d, src, clamp, no_border, FloatFilter::Linear, at, nullptr, out);
        for (int c = 0; c < 4; ++c) out[c] = render_target_value(type, c, out[c]);
      }
  }
  return make_level(format, w, h, rgba.data(), layers);
}

}  // namespace

void generate_mipmaps(Texture& t) {
  if (t.base_level < 0 || t.base_level >= int(t.levels.size())) return t.finalize();
  const Level& base = t.levels[std::size_t(t.base_level)];
  if (base.width <= 0 || base.height <= 0) return t.finalize();
  const int p = last_mip_level(t.base_level, base.width, base.height, t.target == Target::k3D ? base.layers : 1);
  const int q = std::min(p, t.max_level);
  if (int(t.levels.size()) < q + 1) t.levels.resize(std::size_t(q) + 1);
  for (int k = t.base_level + 1; k <= q; ++k) {
    const Level& prev = t.levels[std::size_t(k - 1)];
    t.levels[std::size_t(k)] = downsample(t.format, t.target, prev, std::max(1, prev.width / 2), std::max(1, prev.height / 2));
  }
  t.finalize();
}

}  // namespace tessref::texture
