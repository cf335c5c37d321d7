#pragma once
// Texture lookups on one texture, one invocation at a time: GL 4.6 8.14 (level of detail,
// minification and magnification, mipmapping), 8.14.2 (wrapping and texel selection) and
// 11.1.3.5 (an incomplete texture reads (0, 0, 0, 1)). Where GL leaves the arithmetic to the
// implementation (the LOD's log2 and its rounding, filter weight precision, how coordinates
// become texel indices), this is llvmpipe's arithmetic operation for operation, as read from Mesa
// 22.3.6's gallivm sampler and measured bit for bit (docs/textures.md lists each rule).
#include "texture/filter.h"
#include "texture/texture.h"

namespace tessref::texture {

// Where a lookup's level of detail comes from.
struct LodInput {
  enum class From { Derivatives, Explicit };
  From from = From::Explicit;
  // Derivatives: ds/dx, dt/dx, ds/dy, dt/dy (and dr/dx, dr/dy for a 3D texture). For an implicit
  // LOD in a fragment shader, the quad's (its top-left pixel's differences to its right and upper
  // neighbours: one LOD per quad); for textureGrad, the invocation's own.
  float dsdx = 0.0f, dtdx = 0.0f, dsdy = 0.0f, dtdy = 0.0f, drdx = 0.0f, drdy = 0.0f;
  bool gradients = false;  // textureGrad: a ρ² that is infinite or NaN counts as 0
  float lod = 0.0f;        // Explicit: textureLod's (an implicit LOD outside fragment shaders: 0)
  bool has_bias = false;   // texture(..., bias) in a fragment shader
  float bias = 0.0f;
  // One LOD for the quad: an implicit LOD without bias in a fragment shader. llvmpipe filters
  // 8-bit normalized textures in fixed point only then (or when min and mag filters agree).
  bool per_quad = false;
  // A cube map's: the direction whose derivatives these are (ds.. dr are then d/dx and d/dy of its
  // x, y and z), the invocation's own or, for the quad's LOD, its first invocation's. They are
  // carried onto that direction's face (cube_face_with_derivatives) before ρ is taken.
  float cube_dir[3] = {0.0f, 0.0f, 0.0f};
};

// What a lookup's context and llvmpipe's vector of invocations (sampled together) change.
struct SampleContext {
  bool seamless_cube = false;  // glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS)
  // Whether another invocation of the vector is filtered with GL_LINEAR (linear_in_vector).
  bool vector_linear = false;
  // Seamless cube maps: whether an invocation of the vector has a corner footprint on the first
  // and on the second level filtered (cube_corners).
  bool vector_corner[2] = {false, false};
};

// An array texture's layer for its layer coordinate r (t of a 1D array, r of a 2D one, q of a
// cube map array, whose layers are its cubes; GL 4.6 8.14.2): clamp(floor(r + 0.5), 0, d - 1),
// exactly (llvmpipe rounds ties to even instead: docs/textures.md); NaN reads layer 0. 0 for a
// texture that is not an array.
int array_layer(const Texture& t, float r);

// texture(), textureLod(), textureGrad(), the Offset and Proj forms at `at`: the filtered,
// swizzled texel. `dref`: a shadow sampler's reference depth (already divided for
// Proj forms), compared when the texture's compare mode is on; every channel of the result is
// then the filtered comparisons. A cube map's (s, t, r) is the direction. `context`: see
// SampleContext (llvmpipe runs a vector of invocations at once, and some of its choices are the
// vector's).
void sample(const Texture& t, const Coords& at, const LodInput& lod, const float* dref, float out[4],
            const SampleContext& context = {});

// textureGather() and textureGatherOffset(): the four texels GL_LINEAR would read on the base
// level (i0 j1, i1 j1, i1 j0, i0 j0), component `component` (0..3) through the swizzle; with
// `dref` (the shadow forms), each texel's comparison as 1 or 0. `at`: s and t (a cube map's
// direction in s, t, r), the layer and the offsets.
void gather(const Texture& t, const Coords& at, int component, const float* dref, bool seamless_cube, float out[4]);

// Whether this lookup counts as GL_LINEAR for the invocations sampled with it: true when the
// texture's minification and magnification filters differ, it is filtered in float and this
// lookup uses GL_LINEAR. When one invocation of llvmpipe's vector does, the others that use
// GL_NEAREST are filtered by rounded linear weights (texture/filter.h, NearestByWeights).
bool linear_in_vector(const Texture& t, const LodInput& lod, bool seamless_cube = false);

// A seamless cube map lookup's share in its vector's choices (SampleContext::vector_corner):
// whether its GL_LINEAR footprint has a corner on the first and on the second level that
// llvmpipe filters for it (the second is filtered for the whole vector when one invocation blends
// two levels, even for those that do not). False for other lookups.
struct CubeCorners {
  bool level[2] = {false, false};
};
CubeCorners cube_corners(const Texture& t, const Coords& at, const LodInput& lod, const SampleContext& context);

// Whether a cube map lookup with an implicit LOD takes its LOD from its own derivatives rather
// than from its quad's first invocation's: with a mip filter, or with a bias (llvmpipe).
bool cube_lod_per_invocation(const Texture& t, bool has_bias);

// texelFetch(): texel (i, j) of layer `layer` (an array's; a 3D texture's slice; else 0) of level base_level + lod; zero
// outside the level or its layers, or for a level outside base_level .. last_level (GL 4.6
// 11.1.3.2 leaves it undefined): (0, 0, 0, 0), with alpha 1 for formats without alpha.
void fetch(const Texture& t, int i, int j, int layer, int lod, float out[4]);

// textureSize(): level base_level + lod's size as GLSL gives it (width; height for 2D targets;
// layers for arrays; a buffer texture's texels, whatever the lod), zeros for a level outside the
// texture's; (1, 1, 1) for an incomplete texture (the 1 x 1 texture Mesa binds in its place).
void level_size(const Texture& t, int lod, int out[3]);
// textureQueryLevels(): last_level - base_level + 1 (1 for an incomplete texture, as above).
int query_levels(const Texture& t);
// textureQueryLod() (GLSL 4.60 8.9.2): (the level that would be accessed relative to
// base_level, as a float; the LOD after both biases and before the LOD range clamp). A cube map's
// from the derivatives carried onto the face of lod.cube_dir.
void query_lod(const Texture& t, const LodInput& lod, float out[2]);

}  // namespace tessref::texture
