#include "texture/texture.h"

#include <algorithm>
#include <bit>
#include <utility>

namespace tessref::texture {

const char* gl_name(Filter f) {
  switch (f) {
    case Filter::Nearest: return "GL_NEAREST";
    case Filter::Linear: return "GL_LINEAR";
    case Filter::NearestMipmapNearest: return "GL_NEAREST_MIPMAP_NEAREST";
    case Filter::LinearMipmapNearest: return "GL_LINEAR_MIPMAP_NEAREST";
    case Filter::NearestMipmapLinear: return "GL_NEAREST_MIPMAP_LINEAR";
    case Filter::LinearMipmapLinear: return "GL_LINEAR_MIPMAP_LINEAR";
  }
  return "?";
}

const char* gl_name(Target t) {
  switch (t) {
    case Target::k1D: return "GL_TEXTURE_1D";
    case Target::k2D: return "GL_TEXTURE_2D";
    case Target::k1DArray: return "GL_TEXTURE_1D_ARRAY";
    case Target::k2DArray: return "GL_TEXTURE_2D_ARRAY";
    case Target::kBuffer: return "GL_TEXTURE_BUFFER";
    case Target::k3D: return "GL_TEXTURE_3D";
    case Target::kRectangle: return "GL_TEXTURE_RECTANGLE";
    case Target::kCube: return "GL_TEXTURE_CUBE_MAP";
    case Target::kCubeArray: return "GL_TEXTURE_CUBE_MAP_ARRAY";
  }
  return "?";
}

const char* gl_name(CompareFunc f) {
  switch (f) {
    case CompareFunc::Never: return "GL_NEVER";
    case CompareFunc::Less: return "GL_LESS";
    case CompareFunc::Equal: return "GL_EQUAL";
    case CompareFunc::Lequal: return "GL_LEQUAL";
    case CompareFunc::Greater: return "GL_GREATER";
    case CompareFunc::Notequal: return "GL_NOTEQUAL";
    case CompareFunc::Gequal: return "GL_GEQUAL";
    case CompareFunc::Always: return "GL_ALWAYS";
  }
  return "?";
}

int last_mip_level(int base, int w, int h, int d) {
  return base + int(std::bit_width(unsigned(std::max({w, h, d})))) - 1;
}

Level level_from_stored(TexelFormat f, int width, int height, int layers, std::vector<std::uint8_t> stored) {
  Level l;
  l.width = width;
  l.height = height;
  l.layers = layers;
  l.stored = std::move(stored);
  l.texels = decode_texels(f, l.stored);
  return l;
}

Level make_level(TexelFormat f, int width, int height, const float* rgba, int layers) {
  const std::size_t texels = std::size_t(width) * std::size_t(height) * std::size_t(layers);
  return level_from_stored(f, width, height, layers, encode_texels(f, rgba, texels));
}

Level make_integer_level(TexelFormat f, int width, int height, const std::int64_t* rgba, int layers) {
  const std::size_t texels = std::size_t(width) * std::size_t(height) * std::size_t(layers);
  return level_from_stored(f, width, height, layers, encode_integer_texels(f, rgba, texels));
}

// GL 4.6 8.17: a texture is complete when its base level exists, an integer format is sampled
// with GL_NEAREST (or GL_NEAREST_MIPMAP_NEAREST) and, for a minification filter
// that uses mipmaps, level_base <= level_max and every level from the base to
// q = min(p, level_max), p = level_base + floor(log2(max(w_b, h_b, d_b))), exists with the size
// max(1, floor(w_b / 2^(k - level_base))) x max(1, floor(h_b / 2^(k - level_base))) (x the same
// of d_b for a 3D texture; an array keeps the base level's layers).
void Texture::finalize() {
  complete = false;
  last_level = base_level;
  const int n = int(levels.size());
  if (target == Target::kBuffer) {  // no levels, filters or completeness (GL 4.6 8.9): its one image
    base_level = last_level = 0;
    complete = n == 1;
    if (!complete) incomplete_reason = "a buffer texture has one image";
    return;
  }
  if (base_level < 0 || base_level >= n || levels[std::size_t(base_level)].width <= 0 ||
      levels[std::size_t(base_level)].height <= 0) {
    incomplete_reason = "it has no level " + std::to_string(base_level) + " (GL_TEXTURE_BASE_LEVEL)";
    return;
  }
  // GL 4.6 8.17: integer formats are not filterable.
  if (info(format).integer() && (sampler.mag_filter != Filter::Nearest ||
                                 (sampler.min_filter != Filter::Nearest && sampler.min_filter != Filter::NearestMipmapNearest))) {
    incomplete_reason = std::string(info(format).gl_name) + " is an integer format, which GL samples only with " +
                        "GL_NEAREST magnification and GL_NEAREST or GL_NEAREST_MIPMAP_NEAREST minification (filters " +
                        gl_name(sampler.min_filter) + ", " + gl_name(sampler.mag_filter) + ")";
    return;
  }
  const Level& base = levels[std::size_t(base_level)];
  const bool three_d = target == Target::k3D;  // its depth halves with each level; an array's layers do not
  const int p = last_mip_level(base_level, base.width, base.height, three_d ? base.layers : 1);
  if (!uses_mipmaps(sampler.min_filter)) {
    // Complete with the base level alone; texelFetch, textureSize and textureQueryLevels still
    // see the levels the storage has, up to max_level (as Mesa's sampler view does).
    last_level = std::max(base_level, std::min({p, max_level, n - 1}));
    complete = true;
    return;
  }
  if (base_level > max_level) {
    incomplete_reason = "GL_TEXTURE_BASE_LEVEL " + std::to_string(base_level) + " is above GL_TEXTURE_MAX_LEVEL " +
                        std::to_string(max_level);
    return;
  }
  const int q = std::min(p, max_level);
  for (int k = base_level + 1; k <= q; ++k) {
    const int w = std::max(1, base.width >> (k - base_level)), h = std::max(1, base.height >> (k - base_level));
    const int layers = three_d ? std::max(1, base.layers >> (k - base_level)) : base.layers;
    if (k >= n) {
      incomplete_reason = std::string("its minification filter ") + gl_name(sampler.min_filter) + " needs levels " +
                          std::to_string(base_level) + " to " + std::to_string(q) + ", and level " +
                          std::to_string(k) + " is missing";
      return;
    }
    const Level& l = levels[std::size_t(k)];
    if (l.width != w || l.height != h || l.layers != layers) {
      auto size = [&](int x, int y, int n) {  // "WxH", "WxH with N layers" for an array, "WxHxD" in 3D
        return std::to_string(x) + "x" + std::to_string(y) +
               (three_d ? "x" + std::to_string(n) : is_array(target) ? " with " + std::to_string(n) + " layers" : "");
      };
      incomplete_reason = "level " + std::to_string(k) + " is " + size(l.width, l.height, l.layers) + ", and GL requires " +
                          size(w, h, layers);
      return;
    }
  }
  last_level = q;
  complete = true;
}

}  // namespace tessref::texture
