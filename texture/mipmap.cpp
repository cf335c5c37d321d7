#include "texture/mipmap.h"

#include <algorithm>
#include <vector>

#include "common/fixed_point.h"
#include "common/srgb.h"
#include "texture/filter.h"

namespace tessref::texture {
namespace {

// Level k + 1 from level k as Mesa makes it on llvmpipe (util_gen_mipmap): a blit of level k into
// level k + 1 that samples level k with GL_LINEAR and GL_CLAMP_TO_EDGE at each new texel's
// centre, through the same sampler as any lookup (8-bit fixed point for 8-bit normalized formats,
// float otherwise), then stores the result as a render target of the format would: rounded to
// 8 bits, sRGB-encoded, or a half rounded toward zero (common/fixed_point.h). For an even size
// that is the mean of a 2 x 2 block; an odd size weighs two texels at the centre, not three.
Level downsample(TexelFormat format, const Level& src, int w, int h) {
  const Axes clamp{{Wrap::ClampToEdge, Wrap::ClampToEdge}, {false, false}};
  const std::array<float, 4> no_border{};
  const ChannelType type = info(format).type;
  std::vector<float> rgba(std::size_t(w) * std::size_t(h) * 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float s = (float(x) + 0.5f) / float(w), t = (float(y) + 0.5f) / float(h);
      float* out = rgba.data() + (std::size_t(y) * std::size_t(w) + std::size_t(x)) * 4;
      if (type == ChannelType::kUnorm8) {
        std::uint8_t texel[4];
        filter_unorm8(format, src, clamp, true, s, t, 0, 0, texel);
        for (int c = 0; c < 4; ++c) out[c] = fixed::unorm8_to_float(texel[c]);  // exact k / 255: encodes to k
        continue;
      }
      filter_float(src, clamp, no_border, FloatFilter::Linear, s, t, 0, 0, nullptr, out);
      for (int c = 0; c < 4; ++c) {
        if (type == ChannelType::kFloat16) out[c] = fixed::half_round_toward_zero(out[c]);
        if (type == ChannelType::kSrgb8 && c < 3) out[c] = fixed::unorm8_to_float(srgb_encode(out[c]));
      }
    }
  return make_level(format, w, h, rgba.data());
}

}  // namespace

void generate_mipmaps(Texture& t) {
  if (t.base_level < 0 || t.base_level >= int(t.levels.size())) return t.finalize();
  const Level& base = t.levels[std::size_t(t.base_level)];
  if (base.width <= 0 || base.height <= 0) return t.finalize();
  const int p = last_mip_level(t.base_level, base.width, base.height);
  const int q = std::min(p, t.max_level);
  if (int(t.levels.size()) < q + 1) t.levels.resize(std::size_t(q) + 1);
  for (int k = t.base_level + 1; k <= q; ++k) {
    const Level& prev = t.levels[std::size_t(k - 1)];
    t.levels[std::size_t(k)] = downsample(t.format, prev, std::max(1, prev.width / 2), std::max(1, prev.height / 2));
  }
  t.finalize();
}

}  // namespace tessref::texture
