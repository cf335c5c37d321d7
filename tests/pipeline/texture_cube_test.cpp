// Cube maps (GL 4.6 8.13): face selection and coordinates by table 8.19, the texels seamless
// filtering takes from a face's neighbours, and the scene keys of cube map textures.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/error.h"
#include "render/texture_load.h"
#include "scene/scene_loader.h"
#include "texture/cube.h"
#include "texture/sample.h"

namespace tessref {
namespace {

const std::string kSweep = std::string(TESSREF_SOURCE_DIR) + "/tests/data/draws/sampling_sweep.json";

// GL 4.6 table 8.19: the major axis picks the face, s_c and t_c are signed minor coordinates, and
// s = (s_c / |m_a| + 1) / 2, exact here (dyadic values).
TEST(CubeFace, MajorAxisAndFaceCoordinatesAreTable819) {
  struct Case {
    float x, y, z;
    int face;
    float s, t;
  };
  const Case cases[] = {
      {1.0f, 0.5f, -0.25f, 0, 0.625f, 0.25f},    // +X: s_c = -r_z, t_c = -r_y
      {-2.0f, 0.5f, -0.25f, 1, 0.4375f, 0.375f},  // -X: s_c = r_z, t_c = -r_y
      {0.5f, 1.0f, -0.25f, 2, 0.75f, 0.375f},     // +Y: s_c = r_x, t_c = r_z
      {0.5f, -1.0f, -0.25f, 3, 0.75f, 0.625f},    // -Y: s_c = r_x, t_c = -r_z
      {0.5f, -0.25f, 1.0f, 4, 0.75f, 0.625f},     // +Z: s_c = r_x, t_c = -r_y
      {0.5f, -0.25f, -1.0f, 5, 0.25f, 0.625f},    // -Z: s_c = -r_x, t_c = -r_y
      // Ties: z over x and y, then y over x (llvmpipe's order; GL leaves it open).
      {1.0f, 1.0f, 0.0f, 2, 1.0f, 0.5f},
      {1.0f, -1.0f, 1.0f, 4, 1.0f, 1.0f},
      {-1.0f, 0.0f, -1.0f, 5, 1.0f, 0.5f},
      // The sign bit picks the face: -0 is the negative one; a zero direction reads the centre.
      {0.0f, 0.0f, 0.0f, 4, 0.5f, 0.5f},
      {0.0f, 0.0f, -0.0f, 5, 0.5f, 0.5f},
  };
  for (const Case& c : cases) {
    const texture::CubeFace f = texture::cube_face(c.x, c.y, c.z);
    EXPECT_EQ(f.face, c.face) << c.x << " " << c.y << " " << c.z;
    EXPECT_EQ(f.s, c.s) << c.x << " " << c.y << " " << c.z;
    EXPECT_EQ(f.t, c.t) << c.x << " " << c.y << " " << c.z;
  }
}

// With derivatives the coordinates agree (to the rounding of 0.5 * (1/m_a) against 0.5 / |m_a|),
// and ds/dx is the derivative of s = s_c / (2 |m_a|) + 1/2: moving along +X's s_c = -r_z by d
// at m_a = 2 moves s by d / 4; moving the major axis scales s_c's share.
TEST(CubeFace, DerivativesAreCarriedOntoTheFace) {
  const float dir[3] = {2.0f, 0.5f, -1.0f}, dx[3] = {0.0f, 0.0f, -0.25f}, dy[3] = {0.5f, 0.0f, 0.0f};
  float d[4];
  const texture::CubeFace f = texture::cube_face_with_derivatives(dir, dx, dy, d);
  const texture::CubeFace g = texture::cube_face(dir[0], dir[1], dir[2]);
  EXPECT_EQ(f.face, 0);
  EXPECT_EQ(f.s, g.s);
  EXPECT_EQ(f.t, g.t);
  EXPECT_EQ(d[0], 0.0625f);  // s_c = -r_z: +0.25 over 2 |m_a| = 4
  EXPECT_EQ(d[1], 0.0f);     // t_c = -r_y does not move
  // Along x (the major axis) by 0.5: s_c = 1 and t_c = -0.5 are divided by a larger m_a:
  // ds = (0 - (0.5 / 2) * 1) * (0.5 / 2) = -1/16, dt = (0 - (0.5 / 2) * -0.5) * 0.25 = 1/32.
  EXPECT_EQ(d[2], -0.0625f);
  EXPECT_EQ(d[3], 0.03125f);
}

// The direction to (s, t) on a face: table 8.19 inverted, with s_c = 2s - 1 and t_c = 2t - 1.
void face_direction(int face, float s, float t, float out[3]) {
  const float sc = 2.0f * s - 1.0f, tc = 2.0f * t - 1.0f;
  const float dirs[6][3] = {{1.0f, -tc, -sc}, {-1.0f, -tc, sc}, {sc, 1.0f, tc}, {sc, -1.0f, -tc}, {sc, -tc, 1.0f}, {-sc, -tc, -1.0f}};
  for (int c = 0; c < 3; ++c) out[c] = dirs[face][c];
}

// The direction to texel (i, j)'s centre on an n x n face.
void texel_direction(int face, int i, int j, int n, float out[3]) {
  face_direction(face, (float(i) + 0.5f) / float(n), (float(j) + 0.5f) / float(n), out);
}

float angle(const float a[3], const float b[3]) {
  const double dot = double(a[0]) * b[0] + double(a[1]) * b[1] + double(a[2]) * b[2];
  const double la = std::sqrt(double(a[0]) * a[0] + double(a[1]) * a[1] + double(a[2]) * a[2]);
  const double lb = std::sqrt(double(b[0]) * b[0] + double(b[1]) * b[1] + double(b[2]) * b[2]);
  return float(std::acos(std::clamp(dot / (la * lb), -1.0, 1.0)));
}

// Seamless filtering's footprint (textureGather, seamless): every texel it reads, on whichever
// face, lies next to the lookup's direction (within 1.5 texels' angle), for lookups all over every
// face, up to its edges and corners; at a corner the missing texel is the mean of the other three.
TEST(CubeSeamless, FootprintTexelsAreTheDirectionsNeighbours) {
  constexpr int n = 8;
  std::vector<float> rgba;  // each texel holds (face, i, j, 1)
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) rgba.insert(rgba.end(), {float(face), float(i), float(j), 1.0f});
  const texture::Level level = texture::make_level(texture::TexelFormat::kRgba32F, n, n, rgba.data(), 6);
  const float texel_angle = 2.0f / float(n);  // a texel's width at a face's centre, in radians
  int corners = 0, lookups = 0;
  for (int face = 0; face < 6; ++face)
    for (int v = 0; v <= 4 * n; ++v)
      for (int u = 0; u <= 4 * n; ++u) {
        // s and t from 0 to 1 in steps of a quarter texel: texel centres, edges and the face's edges.
        const float s = float(u) / float(4 * n), t = float(v) / float(4 * n);
        float dir[3];
        face_direction(face, s, t, dir);
        const texture::CubeFace at = texture::cube_face(dir[0], dir[1], dir[2]);
        float f[4], i[4], j[4];
        texture::gather_cube_seamless(level, 0, at, 0, nullptr, true, f);
        texture::gather_cube_seamless(level, 0, at, 1, nullptr, true, i);
        texture::gather_cube_seamless(level, 0, at, 2, nullptr, true, j);
        const bool corner = texture::cube_corner(n, at);
        corners += corner;
        ++lookups;
        // Which texel a corner lacks: gather's order is (i0, j1), (i1, j1), (i1, j0), (i0, j0).
        const float cs = std::floor(at.s * float(n) - 0.5f), ct = std::floor(at.t * float(n) - 0.5f);
        const bool high_i = cs + 1.0f > float(n - 1), high_j = ct + 1.0f > float(n - 1);
        const int missing = !corner ? -1 : high_j ? (high_i ? 1 : 0) : (high_i ? 2 : 3);
        float others = 0.0f;
        for (int k = 0; k < 4; ++k) {
          if (k == missing) continue;
          others += f[k];
          float centre[3];
          texel_direction(int(f[k]), int(i[k]), int(j[k]), n, centre);
          EXPECT_LT(angle(dir, centre), 1.5f * texel_angle)
              << "face " << face << " s " << s << " t " << t << " texel " << k << ": face " << f[k] << " (" << i[k] << ", "
              << j[k] << ")";
        }
        if (corner) {
          EXPECT_FLOAT_EQ(f[missing], others / 3.0f) << "face " << face << " s " << s << " t " << t;
        }
      }
  EXPECT_EQ(lookups, 6 * 33 * 33);
  // Corners: s and t each among the 2 quarter-texel steps below half a texel (0, 1/4) or the 3 from
  // half a texel from the top (7.5, 7.75, 8 in texels), so 5 x 5 per face.
  EXPECT_EQ(corners, 6 * 25);
}

// Seamless GL_LINEAR of a constant cube map is that constant everywhere, corners included (the
// corner's weight goes to the other three), whether its vector sums by weight or interpolates.
TEST(CubeSeamless, ConstantCubeMapFiltersToItsValue) {
  texture::Texture t;
  t.target = texture::Target::kCube;
  const std::vector<float> rgba(std::size_t(4 * 4 * 6 * 4), 0.375f);
  t.levels.push_back(texture::make_level(texture::TexelFormat::kRgba32F, 4, 4, rgba.data(), 6));
  t.sampler.min_filter = texture::Filter::Linear;
  t.finalize();
  ASSERT_TRUE(t.complete) << t.incomplete_reason;
  for (bool corner_in_vector : {false, true})
    for (const auto& d : std::vector<std::array<float, 3>>{{1.0f, 1.0f, 1.0f}, {-1.0f, 0.99f, -0.98f}, {0.2f, -1.0f, 0.1f}}) {
      texture::SampleContext context;
      context.seamless_cube = true;
      context.vector_corner[0] = corner_in_vector;
      float out[4];
      texture::sample(t, texture::Coords{d[0], d[1], d[2]}, texture::LodInput{}, nullptr, out, context);
      for (int c = 0; c < 4; ++c) EXPECT_FLOAT_EQ(out[c], 0.375f) << d[0] << " " << d[1] << " " << d[2];
    }
}

// Without seamless filtering GL 4.6 8.14.2 applies the wrap modes to each face (llvmpipe clamps to
// the edge whatever they are: docs/textures.md); with it the wraps are ignored and the texels past
// the edge are the neighbour's. Each texel holds (face, i, j, 1); the lookup is a quarter texel
// inside +X's left edge (s = 1/32 on a 4 x 4 face: texels -1 and 0 with weights 0.375 and 0.625).
TEST(CubeSeamless, WrapModesApplyPerFaceOnlyWithoutSeamlessFiltering) {
  constexpr int n = 4;
  std::vector<float> rgba;
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) rgba.insert(rgba.end(), {float(face), float(i), float(j), 1.0f});
  auto lookup = [&](texture::Wrap wrap, bool seamless, float out[4]) {
    texture::Texture t;
    t.target = texture::Target::kCube;
    t.levels.push_back(texture::make_level(texture::TexelFormat::kRgba32F, n, n, rgba.data(), 6));
    t.sampler.min_filter = t.sampler.mag_filter = texture::Filter::Linear;
    t.sampler.wrap_s = t.sampler.wrap_t = wrap;
    t.finalize();
    texture::SampleContext context;
    context.seamless_cube = seamless;
    texture::sample(t, texture::Coords{1.0f, 0.0f, 0.9375f}, texture::LodInput{}, nullptr, out, context);
  };
  float out[4];
  lookup(texture::Wrap::Repeat, false, out);  // texel 3 of the same face, then texel 0
  EXPECT_EQ(out[0], 0.0f);
  EXPECT_EQ(out[1], 1.125f);
  lookup(texture::Wrap::ClampToEdge, false, out);  // texel 0 twice
  EXPECT_EQ(out[0], 0.0f);
  EXPECT_EQ(out[1], 0.0f);
  for (texture::Wrap wrap : {texture::Wrap::Repeat, texture::Wrap::ClampToBorder}) {
    lookup(wrap, true, out);  // +X's left neighbour is +Z (face 4): 0.375 of it
    EXPECT_EQ(out[0], 1.5f);
  }
}

std::string error_of(const std::vector<std::string>& sets) {
  try {
    std::vector<std::string> full;
    for (const std::string& s : sets) full.push_back("draws.0.shaders." + s);
    const Scene scene = load_scene(kSweep, full);
    load_texture(scene.draws[0].shaders->textures[0], "u_tex", scene);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

std::string faces(int n, const std::string& first = "cube_16_face0.png") {
  std::string out = "[\"sampling/" + first + "\"";
  for (int k = 1; k < n; ++k) out += ", \"sampling/cube_16_face" + std::to_string(k) + ".png\"";
  return out + "]";
}

TEST(CubeScene, CubeMapsAreCheckedByKey) {
  auto cube = [](const std::string& target, const std::string& keys) {
    return "textures.u_tex={\"path\": null, \"target\": \"" + target + "\", \"internalformat\": \"GL_RGBA8\", " + keys + "}";
  };
  auto expect = [](const std::vector<std::string>& sets, const std::string& message) {
    const std::string e = error_of(sets);
    EXPECT_NE(e.find(message), std::string::npos) << e;
  };
  expect({cube("GL_TEXTURE_CUBE_MAP", "\"layers\": " + faces(5))},
         "draws.0.shaders.textures.u_tex.layers: a GL_TEXTURE_CUBE_MAP has six faces (+X, -X, +Y, -Y, +Z, -Z), and this "
         "gives 5 image files");
  expect({cube("GL_TEXTURE_CUBE_MAP_ARRAY", "\"layers\": " + faces(8))},
         "draws.0.shaders.textures.u_tex.layers: a GL_TEXTURE_CUBE_MAP_ARRAY's layers come six per cube (+X, -X, +Y, -Y, "
         "+Z, -Z), and this gives 8 image files");
  expect({cube("GL_TEXTURE_CUBE_MAP", "\"path\": \"sampling/cube_16_face0.png\"")},
         "draws.0.shaders.textures.u_tex.path: a GL_TEXTURE_CUBE_MAP's image files are its faces: give layers (level 0's "
         "faces, +X, -X, +Y, -Y, +Z, -Z), or raw bytes of every face with raw_size");
  expect({cube("GL_TEXTURE_CUBE_MAP", "\"path\": \"sampling/noise_bytes_0.raw\", \"raw_size\": [64, 32]")},
         "draws.0.shaders.textures.u_tex.raw_size: a cube map's faces are square (glTexStorage refuses a width that is not "
         "the height: GL_INVALID_VALUE), got 64x32");
  expect({cube("GL_TEXTURE_CUBE_MAP_ARRAY", "\"path\": \"sampling/noise_bytes_0.raw\", \"raw_size\": [16, 16, 8]")},
         "draws.0.shaders.textures.u_tex.raw_size: a GL_TEXTURE_CUBE_MAP_ARRAY's layers come six per cube "
         "(glTexStorage3D: GL_INVALID_VALUE), got 8");
  std::string oblong = "[\"sampling/noise_24x10.png\"";
  for (int k = 1; k < 6; ++k) oblong += ", \"sampling/noise_24x10.png\"";
  expect({cube("GL_TEXTURE_CUBE_MAP", "\"layers\": " + oblong + "]")},
         "/tests/data/draws/sampling/noise_24x10.png is 24x10, and a cube map's faces are square");
  // Raw bytes of every face: six 16 x 16 faces of GL_RGBA8 in a 6,144-byte level.
  EXPECT_NE(error_of({cube("GL_TEXTURE_CUBE_MAP", "\"path\": \"sampling/noise_bytes_2.raw\", \"raw_size\": [16, 16]")})
                .find("has 4096 bytes, and level 0 of GL_RGBA8 is 16x16x6 texels of 4 bytes: 6144 (raw_size)"),
            std::string::npos);
  // Twelve faces are two cubes; textureSize's third component counts cubes.
  const Scene scene = load_scene(kSweep, {"draws.0.shaders." + cube("GL_TEXTURE_CUBE_MAP_ARRAY", "\"layers\": " + faces(12) +
                                                                         ", \"generate_mipmap\": true")});
  const texture::Texture t = load_texture(scene.draws[0].shaders->textures[0], "u_tex", scene);
  ASSERT_TRUE(t.complete) << t.incomplete_reason;
  EXPECT_EQ(t.levels.size(), 5u);
  EXPECT_EQ(t.levels[4].layers, 12);
  int size[3];
  texture::level_size(t, 1, size);
  EXPECT_EQ(size[0], 8);
  EXPECT_EQ(size[1], 8);
  EXPECT_EQ(size[2], 2);
  EXPECT_EQ(texture::array_layer(t, 1.4f), 1);
  EXPECT_EQ(texture::array_layer(t, 7.0f), 1);
}

TEST(CubeScene, SeamlessFilteringIsADrawCapability) {
  const Scene scene = load_scene(kSweep, {"draws.0.enable=[\"GL_TEXTURE_CUBE_MAP_SEAMLESS\", \"GL_BLEND\"]"});
  EXPECT_TRUE(scene.draws[0].raster.cube_map_seamless);
  EXPECT_FALSE(load_scene(kSweep, {}).draws[0].raster.cube_map_seamless);
}

}  // namespace
}  // namespace tessref
