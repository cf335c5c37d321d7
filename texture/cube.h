#pragma once
// Cube maps (GL 4.6 8.13): which face a direction points at and where on it, the derivatives
// carried onto that face for the level of detail, and seamless filtering across faces
// (GL_TEXTURE_CUBE_MAP_SEAMLESS), as llvmpipe computes them (Mesa 22.3.6: lp_build_cube_lookup,
// lp_build_cube_new_coords, lp_build_sample_image_linear; docs/textures.md has the rules).
#include <array>

#include "texture/filter.h"
#include "texture/texture.h"

namespace tessref::texture {

// A face (0 to 5: +X, -X, +Y, -Y, +Z, -Z, as GL numbers the layers of a cube) and (s, t) on it.
struct CubeFace {
  int face = 0;
  float s = 0.0f, t = 0.0f;
};

// GL 4.6 table 8.19's selection: z when |r_z| >= max(|r_x|, |r_y|), else x when |r_x| > |r_y|,
// else y; the major coordinate's sign bit picks the negative face. s = s_c * (0.5 / |m_a|) + 0.5
// (0 in place of 0.5 / |m_a| when m_a is 0); on llvmpipe's derivative path (`derivative_path`)
// s = s_c * |0.5 * (1/m_a)| + 0.5, which can round differently.
CubeFace cube_face(float x, float y, float z, bool derivative_path = false);

// The same face with the derivatives of the direction (dx, dy: d/dx and d/dy of x, y and z)
// carried onto it, for the LOD: ds = (ds_c - (dm_a * (1/m_a)) * s_c) * (0.5 * (1/m_a)), likewise
// for t. The coordinates are cube_face's on the derivative path. `d` gets ds/dx, dt/dx, ds/dy,
// dt/dy.
CubeFace cube_face_with_derivatives(const float dir[3], const float dx[3], const float dy[3], float d[4]);

// How one level of a cube map is filtered seamlessly: GL_LINEAR's four texels, those that fall
// off the face read from its neighbours. `corner_in_vector`: whether an invocation sampled in the
// same vector as this one has a corner footprint (one texel on no face) on this level, as
// cube_corner says; llvmpipe then sums w00·t00 + w01·t01 + w10·t10 + w11·t11 with the corner's
// weight split in thirds among the other three for the whole vector, and interpolates otherwise.
// `first_layer`: the cube's first layer (6 × its index in a cube map array).
void filter_cube_seamless(const Level& level, int first_layer, const CubeFace& at, FloatFilter filter,
                          const DepthCompare* compare, bool corner_in_vector, float out[4]);

// Whether GL_LINEAR's footprint at `at` on a level `size` texels wide falls off two edges of its
// face at once (a corner).
bool cube_corner(int size, const CubeFace& at);

// textureGather on a cube map with seamless filtering: the four texels GL_LINEAR reads (in
// gather's order: i0 j1, i1 j1, i1 j0, i0 j0), channel `channel` or the comparison's 1 or 0; at a
// corner the missing texel is the mean of the other three (`average_corner`; llvmpipe keeps the
// texel it read in its place for integer formats).
void gather_cube_seamless(const Level& level, int first_layer, const CubeFace& at, int channel,
                          const DepthCompare* compare, bool average_corner, float out[4]);

}  // namespace tessref::texture
