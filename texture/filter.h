#pragma once
// One mip level filtered at one coordinate: how (s, t) becomes texel indices and weights for
// each wrap mode, and how the texels are combined, as llvmpipe's sampler computes them (GL 4.6
// 8.14.2 gives the same texels and weights in exact arithmetic; docs/textures.md has the rules).
#include <array>
#include <cstdint>

#include "texture/texture.h"

namespace tessref::texture {

// The wrap mode of s, t and r, and whether level 0's width, height and depth are powers of two
// (llvmpipe wraps REPEAT with a mask then, and through the coordinate's fraction otherwise). A 1D
// texture (dims 1) is filtered along s alone: its one row, t and its wrap unused; the filters
// below take one slice, and a 3D texture's r is resolved by axis_texels.
struct Axes {
  std::array<Wrap, 3> wrap;
  std::array<bool, 3> pot;
  int dims = 2;
  bool normalized = true;  // false: a rectangle texture's coordinates, in texels (clamp wraps only)
};

// Along one axis of `size` texels (a 3D texture's r): the texels a lookup reads, -1 for the
// border colour, and the second one's weight. GL_NEAREST reads k0 alone (weight 0); GL_LINEAR in
// float gives `weight`, on the 8-bit path `weight8` (in 256ths), as the filters below compute
// them for s and t.
struct AxisTexels {
  std::int32_t k0 = 0, k1 = 0;
  float weight = 0.0f;
  std::int32_t weight8 = 0;
};
AxisTexels axis_texels(float c, int size, int offset, Wrap wrap, bool pot, bool linear, bool unorm8);

// Formats of 8-bit normalized channels, filtered in 8-bit fixed point (repeat and clamp-to-edge
// only): the channels, four per texel (missing green and blue 0, missing alpha 255).
void filter_unorm8(TexelFormat format, const LevelSlice& level, const Axes& axes, bool linear, float s, float t,
                   int offset_s, int offset_t, std::uint8_t out[4]);

// How filter_float filters. NearestByWeights: GL_NEAREST as llvmpipe computes it for the
// magnified pixels of a vector that also has minified ones (or the reverse): the GL_LINEAR
// texel pair and weights, each weight rounded to 0 or 1 (above one half: 1), then interpolated
// as for GL_LINEAR. That picks the nearer texel, the lower one at an exact tie, and returns
// t0 + (t1 - t0) for t1, which can differ from t1 in the last bit.
enum class FloatFilter { Nearest, Linear, NearestByWeights };

// A depth comparison (GL 4.6 8.23.1): each texel's depth D_t tested as "ref FUNC D_t" gives 1 or
// 0, and those are filtered instead of the texels (llvmpipe: ordered comparisons, but NOTEQUAL
// unordered, so a NaN passes NOTEQUAL alone).
struct DepthCompare {
  CompareFunc func;
  float ref;
};
bool passes(const DepthCompare& c, float depth);

// Every other format and wrap, in float: the texels as decoded, border texels as `border`. With a
// comparison, every channel of the result is the filtered 1s and 0s: for GL_LINEAR, per row
// (w where the second passes) + (1 - w where the first does), then the rows interpolated.
void filter_float(const LevelSlice& level, const Axes& axes, const std::array<float, 4>& border, FloatFilter filter,
                  float s, float t, int offset_s, int offset_t, const DepthCompare* compare, float out[4]);

// textureGather (GL 4.6 8.14.2): GL_LINEAR's four texels at (s, t), in the order (i0, j1),
// (i1, j1), (i1, j0), (i0, j0): channel `channel` of each, or with a comparison its 1 or 0.
void gather_float(const LevelSlice& level, const Axes& axes, const std::array<float, 4>& border, float s, float t,
                  int offset_s, int offset_t, int channel, const DepthCompare* compare, float out[4]);

// GL_TEXTURE_BORDER_COLOR as the sampler uses it: clamped to [0, 1] for normalized formats.
std::array<float, 4> border_color(const Texture& t);

}  // namespace tessref::texture
