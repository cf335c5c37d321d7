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
// below take one slice, and filter_level_* resolve a 3D texture's r.
struct Axes {
  std::array<Wrap, 3> wrap;
  std::array<bool, 3> pot;
  int dims = 2;
  bool normalized = true;  // false: a rectangle texture's coordinates, in texels (clamp wraps only)
};

// Where a lookup samples: s, t and r (those the target has; already divided for Proj forms), the
// layer of an array (array_layer; 0 otherwise), and textureOffset's texel offsets.
struct Coords {
  float s = 0.0f, t = 0.0f, r = 0.0f;
  int layer = 0;
  int offset_s = 0, offset_t = 0, offset_r = 0;
};

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

// One level filtered at `at`: its layer at.layer (0 unless an array) as above, or for a 3D texture
// (three_d) the two slices nearest r, each filtered so, interpolated by r's weight
// (lp_build_lerp_3d: s, then t, then r); a slice outside a GL_CLAMP_TO_BORDER texture reads
// `border`. On the 8-bit path, r's wrap must be repeat or clamp-to-edge too.
void filter_level_unorm8(TexelFormat format, bool three_d, const Level& level, const Axes& axes, bool linear,
                         const Coords& at, std::uint8_t out[4]);
void filter_level_float(bool three_d, const Level& level, const Axes& axes, const std::array<float, 4>& border,
                        FloatFilter filter, const Coords& at, const DepthCompare* compare, float out[4]);

// GL_TEXTURE_BORDER_COLOR as the sampler uses it: clamped to [0, 1] for normalized formats.
std::array<float, 4> border_color(const Texture& t);

}  // namespace tessref::texture
