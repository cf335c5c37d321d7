#include "texture/mipmap.h"

#include <algorithm>
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

// Level k + 1 from level k as Mesa makes it on llvmpipe (util_gen_mipmap): a blit of level k into
// level k + 1 that samples level k with GL_LINEAR and GL_CLAMP_TO_EDGE at each new texel's
// centre, through the same sampler as any lookup (8-bit fixed point for 8-bit normalized formats,
// float otherwise), then stores the result as llvmpipe's render target of the format stores it
// (render_target_value). For an even size that is the mean of a 2 x 2 block; an odd size weighs
// two texels at the centre, not three.
// An array's layers are blitted one by one; a 3D texture's new slice z samples its two nearest
// slices at r = (z + 0.5) / depth, each as a 2D level, and interpolates them (as lerp_3d does).
Level downsample(TexelFormat format, Target target, const Level& src, int w, int h) {
  const Axes clamp{{Wrap::ClampToEdge, Wrap::ClampToEdge, Wrap::ClampToEdge}, {false, false, false}, dimensions(target)};
  const std::array<float, 4> no_border{};
  const ChannelType type = info(format).type;
  const bool unorm8 = type == ChannelType::kUnorm8, three_d = target == Target::k3D;
  const int layers = three_d ? std::max(1, src.layers / 2) : src.layers;
  std::vector<float> rgba(std::size_t(w) * std::size_t(h) * std::size_t(layers) * 4);
  for (int layer = 0; layer < layers; ++layer) {
    float* to = rgba.data() + std::size_t(layer) * std::size_t(w) * std::size_t(h) * 4;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        // An array's layer is itself; a 3D texture's new slice samples r at its centre.
        const Coords at{(float(x) + 0.5f) / float(w), (float(y) + 0.5f) / float(h),
                        three_d ? (float(layer) + 0.5f) / float(layers) : 0.0f, three_d ? 0 : layer};
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
