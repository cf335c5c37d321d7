#pragma once
// A GL texture as the sampler sees it: a 1D, 2D or 3D image, a cube map (or an array of 1D or 2D
// images or of cube maps) with its mip levels, or a buffer
// texture's texels, in the internal format its texels were converted to, with the texture's and sampler object's
// state (GL 4.6 8.10 and 8.14).
// Plain data: the scene loader fills it, the executor reads it through texture/sample.h.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "texture/texel_format.h"

namespace tessref::texture {

// The texture targets tessref samples (GL 4.6 8.1).
enum class Target : std::uint8_t { k1D, k2D, k1DArray, k2DArray, kBuffer, k3D, kRectangle, kCube, kCubeArray };
const char* gl_name(Target t);
inline bool is_cube(Target t) { return t == Target::kCube || t == Target::kCubeArray; }
// The coordinates that address a texel within a layer: 1 (1D textures and their arrays, buffer
// textures), 2 (a cube map's within a face) or 3.
inline int dimensions(Target t) {
  return t == Target::k3D                                                                       ? 3
         : t == Target::k2D || t == Target::k2DArray || t == Target::kRectangle || is_cube(t) ? 2
                                                                                                : 1;
}
// The coordinates a lookup gives before an array's layer: a cube map's direction has 3.
inline int lookup_dimensions(Target t) { return is_cube(t) ? 3 : dimensions(t); }
inline bool is_array(Target t) { return t == Target::k1DArray || t == Target::k2DArray || t == Target::kCubeArray; }

// GL_TEXTURE_MIN_FILTER / GL_TEXTURE_MAG_FILTER (the magnification filter is Nearest or Linear).
enum class Filter {
  Nearest, Linear,
  NearestMipmapNearest, LinearMipmapNearest, NearestMipmapLinear, LinearMipmapLinear,
};
// GL_TEXTURE_WRAP_S / _T / _R.
enum class Wrap { Repeat, MirroredRepeat, ClampToEdge, ClampToBorder, MirrorClampToEdge };
// GL_TEXTURE_COMPARE_FUNC: the test "D_ref FUNC D_texel" of GL 4.6 table 8.21.
enum class CompareFunc { Never, Less, Equal, Lequal, Greater, Notequal, Gequal, Always };
// GL_TEXTURE_SWIZZLE_R/G/B/A: which component (or constant) each result component reads.
enum class Swizzle : std::uint8_t { Red, Green, Blue, Alpha, Zero, One };

// GL_MAX_TEXTURE_SIZE on llvmpipe; the sampler's fixed-point coordinates rely on it.
inline constexpr int kMaxTextureSize = 16384;
// GL_MAX_3D_TEXTURE_SIZE on llvmpipe.
inline constexpr int kMax3DTextureSize = 2048;
// GL_MAX_ARRAY_TEXTURE_LAYERS on llvmpipe (a cube map array's layer-faces too).
inline constexpr int kMaxArrayLayers = 2048;
// GL_MAX_CUBE_MAP_TEXTURE_SIZE on llvmpipe.
inline constexpr int kMaxCubeMapTextureSize = 16384;
// GL_MAX_TEXTURE_BUFFER_SIZE on llvmpipe (texels): a buffer texture's range holds at most this many.
inline constexpr std::int64_t kMaxTextureBufferSize = 134217728;

const char* gl_name(Filter f);
const char* gl_name(CompareFunc f);
// p of GL 4.6 8.17: the last level of a full mip chain whose level `base` is w x h.
int last_mip_level(int base, int w, int h, int d = 1);
inline bool uses_mipmaps(Filter f) { return f != Filter::Nearest && f != Filter::Linear; }

// Sampler state (a sampler object's, or the texture's own when no sampler object is bound),
// with GL's initial values.
struct SamplerState {
  Filter min_filter = Filter::NearestMipmapLinear;
  Filter mag_filter = Filter::Linear;
  Wrap wrap_s = Wrap::Repeat, wrap_t = Wrap::Repeat, wrap_r = Wrap::Repeat;
  std::array<float, 4> border{0.0f, 0.0f, 0.0f, 0.0f};  // GL_TEXTURE_BORDER_COLOR
  // The border colour an integer format reads, as glTexParameterIiv / Iuiv give it.
  std::array<std::int64_t, 4> border_integer{0, 0, 0, 0};
  float min_lod = -1000.0f, max_lod = 1000.0f;           // GL_TEXTURE_MIN_LOD / MAX_LOD
  float lod_bias = 0.0f;                                 // GL_TEXTURE_LOD_BIAS
  bool compare = false;                   // GL_TEXTURE_COMPARE_MODE COMPARE_REF_TO_TEXTURE (else NONE)
  CompareFunc compare_func = CompareFunc::Lequal;  // GL_TEXTURE_COMPARE_FUNC
};

// One layer of one mip level, as the filters read it: width x height texels from `texels` (four
// floats each) and `stored` (the format's bytes).
struct LevelSlice {
  int width = 0, height = 0;
  const float* texels = nullptr;
  const std::uint8_t* stored = nullptr;
};

// One mip level: `layers` images of width x height texels (1 layer unless an array; a 3D
// texture's depth slices; a cube map's 6 faces, +X, -X, +Y, -Y, +Z, -Z, and 6 per cube of a cube
// map array; height 1 for 1D targets and buffer textures), row 0 at the bottom (GL),
// layer after layer. `stored` holds them in the format's own layout (what a driver
// is given); `texels` as the sampler reads them, four floats each (k / 255 for 8-bit normalized
// channels, linear values for sRGB ones, missing green and blue 0, missing alpha 1; integer
// formats: the integers' bits, texture::decode_texels).
struct Level {
  int width = 0, height = 0, layers = 1;
  std::vector<std::uint8_t> stored;
  std::vector<float> texels;
  LevelSlice slice(int layer) const {
    const std::size_t texels_per_layer = std::size_t(width) * std::size_t(height);
    return {width, height, texels.data() + std::size_t(layer) * texels_per_layer * 4,
            stored.data() + std::size_t(layer) * (stored.size() / std::size_t(layers))};
  }
};

// A level of format f from its stored bytes (width x height x layers texels of the format's
// layout), read back by decode_texels.
Level level_from_stored(TexelFormat f, int width, int height, int layers, std::vector<std::uint8_t> stored);
// A level of format f from RGBA floats, 4 per texel, row 0 at the bottom, layer after layer:
// stored in the format and read back (encode_texels, decode_texels).
Level make_level(TexelFormat f, int width, int height, const float* rgba, int layers = 1);
// A level of integer format f from integers, 4 per texel (encode_integer_texels).
Level make_integer_level(TexelFormat f, int width, int height, const std::int64_t* rgba, int layers = 1);

struct Texture {
  Target target = Target::k2D;  // arrays: every level has the same layers
  TexelFormat format = TexelFormat::kRgba32F;
  std::vector<Level> levels;  // levels[k] is mip level k (from level 0, whatever base_level is)
  int base_level = 0;         // GL_TEXTURE_BASE_LEVEL
  int max_level = 1000;       // GL_TEXTURE_MAX_LEVEL
  std::array<Swizzle, 4> swizzle{Swizzle::Red, Swizzle::Green, Swizzle::Blue, Swizzle::Alpha};
  SamplerState sampler;

  // GL 4.6 8.17 (texture completeness), for this sampler state; set by finalize().
  bool complete = false;
  std::string incomplete_reason;  // why not, for the warning
  // q of 8.14.3: the last level (base_level .. max_level, and the levels the texture has).
  int last_level = 0;

  // Checks completeness and sets complete, incomplete_reason and last_level. Call after the
  // levels and state are set.
  void finalize();
};

}  // namespace tessref::texture
