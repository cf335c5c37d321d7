#include "texture/mipmap.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace tessref::texture {
namespace {

float lerp(float w, float v0, float v1) { return v0 + w * (v1 - v0); }

// Level k + 1 from level k: each texel is level k sampled with GL_LINEAR and GL_CLAMP_TO_EDGE at
// the new texel's centre, which for an even size is the mean of a 2 x 2 block. This is what Mesa's
// glGenerateMipmap does on llvmpipe: a blit of each level into the next with linear filtering.
std::vector<float> downsample(const Level& src, int w, int h) {
  std::vector<float> out(std::size_t(w) * std::size_t(h) * 4);
  auto at = [&](int i, int j, int c) {
    i = std::clamp(i, 0, src.width - 1);
    j = std::clamp(j, 0, src.height - 1);
    return src.texels[(std::size_t(j) * std::size_t(src.width) + std::size_t(i)) * 4 + std::size_t(c)];
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float u = (float(x) + 0.5f) / float(w) * float(src.width) - 0.5f;
      const float v = (float(y) + 0.5f) / float(h) * float(src.height) - 0.5f;
      const int i0 = int(std::floor(u)), j0 = int(std::floor(v));
      const float a = u - std::floor(u), b = v - std::floor(v);
      for (int c = 0; c < 4; ++c)
        out[(std::size_t(y) * std::size_t(w) + std::size_t(x)) * 4 + std::size_t(c)] =
            lerp(b, lerp(a, at(i0, j0, c), at(i0 + 1, j0, c)), lerp(a, at(i0, j0 + 1, c), at(i0 + 1, j0 + 1, c)));
    }
  return out;
}

}  // namespace

void generate_mipmaps(Texture& t) {
  if (t.base_level < 0 || t.base_level >= int(t.levels.size())) return t.finalize();
  const Level& base = t.levels[std::size_t(t.base_level)];
  if (base.width <= 0 || base.height <= 0) return t.finalize();
  const int p = t.base_level + int(std::bit_width(unsigned(std::max(base.width, base.height)))) - 1;
  const int q = std::min(p, t.max_level);
  if (int(t.levels.size()) < q + 1) t.levels.resize(std::size_t(q) + 1);
  for (int k = t.base_level + 1; k <= q; ++k) {
    const Level& prev = t.levels[std::size_t(k - 1)];
    const int w = std::max(1, prev.width / 2), h = std::max(1, prev.height / 2);
    const std::vector<float> rgba = downsample(prev, w, h);
    t.levels[std::size_t(k)] = make_level(t.format, w, h, rgba.data());
  }
  t.finalize();
}

}  // namespace tessref::texture
