// Textures in scenes (docs/textures.md) on tessref alone: bad texture descriptions are errors that
// name the key, an incomplete texture is GL's (0, 0, 0, 1) with a warning, and lookups do not
// depend on the thread count or the executor's batch size.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/error.h"
#include "io/image_output.h"
#include "mesh/mesh_source.h"
#include "render/glsl_scene.h"
#include "render/texture_load.h"
#include "render/render.h"
#include "scene/scene_loader.h"
#include "texture/mipmap.h"
#include "texture/sample.h"

namespace tessref {
namespace {

const std::string kSweep = std::string(TESSREF_SOURCE_DIR) + "/tests/data/draws/sampling_sweep.json";

RenderResult render_sweep(std::vector<std::string> sets, int threads = 0) {
  for (std::string& s : sets) s = "draws.0.shaders." + s;
  const Scene scene = load_scene(kSweep, sets);
  std::vector<std::string> warnings;
  return render_scene(scene, build_mesh(scene.mesh, warnings), threads ? Parallel(threads) : Parallel());
}

std::string error_of(const std::vector<std::string>& sets) {
  try {
    render_sweep(sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// The sweep with `sets` fails with an error that contains `message`.
void expect_error(const std::vector<std::string>& sets, const std::string& message) {
  const std::string e = error_of(sets);
  EXPECT_NE(e.find(message), std::string::npos) << e;
}

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

TEST(TextureScene, BadTexturesAreErrorsNamingTheKey) {
  // A file whose channels contradict the declared format.
  EXPECT_NE(error_of({"textures.u_tex.internalformat=\"GL_R8\""})
                .find("draws.0.shaders.textures.u_tex: " + std::string(TESSREF_SOURCE_DIR) +
                      "/tests/data/draws/sampling/noise_64x64.png is RGBA (4 channels), and GL_R8 has 1 channel (internalformat)"),
            std::string::npos)
      << error_of({"textures.u_tex.internalformat=\"GL_R8\""});
  // A format GL does not have for textures here, a filter GL does not have for magnification.
  EXPECT_NE(error_of({"textures.u_tex.internalformat=\"GL_RGBA12\""}).find("draws.0.shaders.textures.u_tex.internalformat: expected one of GL_RGBA32F"),
            std::string::npos);
  EXPECT_NE(error_of({"textures.u_tex.mag_filter=\"linear_mipmap_linear\""}).find("draws.0.shaders.textures.u_tex.mag_filter: expected one of nearest, linear"),
            std::string::npos);
  // The sweep scene with its texture's path replaced by `texture_keys`, and glGenerateMipmap
  // unless `generate`.
  auto edited_error = [](const std::string& texture_keys, bool generate = false) {
    std::ifstream in(kSweep);
    std::stringstream text;
    text << in.rdbuf();
    std::string json = text.str();
    const std::string path = R"("path": "sampling/noise_64x64.png",)";
    json.replace(json.find(path), path.size(), texture_keys);
    if (!generate) json.replace(json.find("\"generate_mipmap\": true"), 23, "\"generate_mipmap\": false");
    try {
      const Scene scene = parse_scene(json, kSweep, std::filesystem::path(kSweep).parent_path());
      std::vector<std::string> warnings;
      render_scene(scene, build_mesh(scene.mesh, warnings), Parallel());
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // A mip level of the wrong size: level 1 of a 64 x 64 texture is 32 x 32.
  const std::string wrong = edited_error(R"("levels": ["sampling/noise_64x64.png", "sampling/noise_24x10.png"],)");
  EXPECT_NE(wrong.find("draws.0.shaders.textures.u_tex.levels.1: level 1 is 24x10, and a level 1 of a 64x64 texture is 32x32"),
            std::string::npos) << wrong;
  // Levels and glGenerateMipmap together (the scene generates), and neither path nor levels.
  const std::string both = edited_error(R"("levels": ["sampling/noise_64x64.png", "sampling/noise_24x10.png"],)", true);
  EXPECT_NE(both.find("draws.0.shaders.textures.u_tex.generate_mipmap: glGenerateMipmap computes levels 1 and up from level 0"),
            std::string::npos) << both;
  const std::string neither = edited_error("");
  EXPECT_NE(neither.find("draws.0.shaders.textures.u_tex.path: give either path (level 0) or levels"), std::string::npos) << neither;
}

// Shadow samplers and depth formats: the mismatches GL leaves undefined are refused, naming the
// key; GL's own refusal (glGenerateMipmap of a depth format) too.
TEST(TextureScene, ShadowSamplerAndDepthFormatMismatchesAreErrorsNamingTheKey) {
  const std::vector<std::string> shadow = {"fragment=\"sampling/lookup_shadow.frag\"", "textures.u_tex.generate_mipmap=false",
                                           "textures.u_tex.min_filter=\"linear\""};
  expect_error(with(shadow, {"textures.u_tex.compare_mode=\"compare_ref_to_texture\""}),
               "draws.0.shaders.textures.u_tex.internalformat: the uniform is a sampler2DShadow, which needs a depth "
               "format (GL_DEPTH_COMPONENT16, 24, 32F or GL_DEPTH24_STENCIL8), not GL_RGBA8");
  const std::vector<std::string> depth = {"textures.u_tex.path=\"sampling/depth_64x64.exr\"",
                                          "textures.u_tex.internalformat=\"GL_DEPTH_COMPONENT24\""};
  expect_error(with(shadow, depth),
               "draws.0.shaders.textures.u_tex.compare_mode: the uniform is a sampler2DShadow, so give "
               "\"compare_ref_to_texture\"");
  expect_error(with(with(depth, {"textures.u_tex.generate_mipmap=false"}),
               {"textures.u_tex.compare_mode=\"compare_ref_to_texture\""}),
               "draws.0.shaders.textures.u_tex.compare_mode: the uniform is a sampler2D, which GL leaves undefined "
               "with GL_COMPARE_REF_TO_TEXTURE");
  const std::string generate = error_of(depth);  // the sweep scene generates mipmaps
  EXPECT_NE(generate.find("draws.0.shaders.textures.u_tex.generate_mipmap: glGenerateMipmap refuses a depth format "
                          "(GL_DEPTH_COMPONENT24 is not color-renderable"),
            std::string::npos) << generate;
  expect_error(with(with(shadow, depth), {"textures.u_tex.compare_mode=\"compare_ref_to_texture\"",
               "textures.u_tex.swizzle=[\"red\", \"red\", \"red\", \"one\"]"}),
               "draws.0.shaders.textures.u_tex.swizzle: tessref does not swizzle a depth comparison's result");
  expect_error(with(with(shadow, depth), {"textures.u_tex.compare_mode=\"compare_ref_to_texture\"",
               "textures.u_tex.compare_func=\"lessequal\""}),
               "draws.0.shaders.textures.u_tex.compare_func: expected one of never, less, equal, lequal");
  // The same keys right: it draws, and every lookup is a comparison's 0 or 1 or a filtered mix.
  EXPECT_EQ(error_of(with(with(shadow, depth), {"textures.u_tex.compare_mode=\"compare_ref_to_texture\""})), "no error");
}

// Depth texels read as llvmpipe converts them: k times the float nearest 1 / (2^b - 1); a float
// depth as stored; D24S8's stencil byte ignored.
TEST(TextureFormat, DepthTexelsReadAsKTimesTheReciprocalOfTheirSteps) {
  const float depths[4] = {0.0f, 1.0f / 3.0f, 0.5f, 1.0f};
  for (const texture::TexelFormat f : {texture::TexelFormat::kDepth16, texture::TexelFormat::kDepth24,
                                       texture::TexelFormat::kDepth32F, texture::TexelFormat::kDepth24Stencil8}) {
    SCOPED_TRACE(texture::info(f).gl_name);
    float rgba[16] = {};
    for (int i = 0; i < 4; ++i) rgba[4 * i] = depths[i];
    const texture::Level level = texture::make_level(f, 4, 1, rgba);
    const int bits = f == texture::TexelFormat::kDepth16 ? 16 : 24;
    for (int i = 0; i < 4; ++i) {
      const float* t = &level.texels[std::size_t(4 * i)];
      if (f == texture::TexelFormat::kDepth32F) {
        EXPECT_EQ(t[0], depths[i]);
      } else {
        const double k = std::nearbyint(double(depths[i]) * double((1u << bits) - 1u));
        EXPECT_EQ(t[0], float(k) * float(1.0 / double((1u << bits) - 1u)));
      }
      EXPECT_EQ(t[1], 0.0f);
      EXPECT_EQ(t[2], 0.0f);
      EXPECT_EQ(t[3], 1.0f);
    }
  }
  // 1/3 in 16 bits is 21845: 21845 * fl(1/65535), which is not the float nearest 1/3.
  float third[4] = {1.0f / 3.0f, 0, 0, 0};
  EXPECT_EQ(texture::make_level(texture::TexelFormat::kDepth16, 1, 1, third).texels[0], 21845.0f * float(1.0 / 65535.0));
}

// Raw texel bytes (raw_size): the PNG's texels written as GL_RGBA8 bytes, bottom row first, draw
// the same image as the PNG; a file of the wrong size is an error naming the key and the sizes.
TEST(TextureScene, RawTexelBytesDrawAsTheImageTheyCameFrom) {
  const Scene scene = load_scene(kSweep);
  std::vector<std::string> warnings;
  const texture::Texture from_png = load_texture(scene.draws[0].shaders->textures[0], "png", scene);
  const std::filesystem::path raw = std::filesystem::temp_directory_path() / "tessref_raw_rgba8.bin";
  {
    std::ofstream out(raw, std::ios::binary);
    out.write(reinterpret_cast<const char*>(from_png.levels[0].stored.data()), std::streamsize(from_png.levels[0].stored.size()));
  }
  const std::vector<std::string> sets = {"textures.u_tex.path=\"" + raw.string() + "\"", "textures.u_tex.raw_size=[64, 64]"};
  const RenderResult a = render_sweep({}), b = render_sweep(sets);
  EXPECT_EQ(a.framebuffer.color, b.framebuffer.color);
  expect_error({"textures.u_tex.path=\"" + raw.string() + "\"", "textures.u_tex.raw_size=[64, 32]"},
               "draws.0.shaders.textures.u_tex: " + raw.string() + " has 16384 bytes, and level 0 of GL_RGBA8 is "
               "64x32 texels of 4 bytes: 8192 (raw_size)");
  expect_error({"textures.u_tex.raw_size=[0, 64]"},
               "draws.0.shaders.textures.u_tex.raw_size: expected [width, height], whole numbers from 1 to 16384");
  std::filesystem::remove(raw);
}

TEST(TextureScene, IncompleteTextureReadsZeroZeroZeroOneWithAWarning) {
  // A mipmap filter with level 0 alone: GL 4.6 8.17 makes it incomplete.
  const RenderResult r = render_sweep({"textures.u_tex.generate_mipmap=false"});
  ASSERT_EQ(r.stats.warnings.size(), 1u);
  EXPECT_NE(r.stats.warnings[0].find("draws.0.shaders.textures.u_tex: the texture is incomplete, so it reads (0, 0, 0, 1): "
                                     "its minification filter GL_LINEAR_MIPMAP_LINEAR needs levels 0 to 6, and level 1 is missing"),
            std::string::npos) << r.stats.warnings[0];
  for (const glm::vec4& c : r.framebuffer.color) ASSERT_EQ(c, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  EXPECT_TRUE(render_sweep({}).stats.warnings.empty());
}

// Integer formats (GL 4.6 8.17, GLSL 4.60 8.9): a sampler type that does not match the format's,
// glGenerateMipmap, a filter other than GL_NEAREST (incomplete, with the reason), a file value
// the format cannot hold and a border colour that is not a whole number are each refused or
// warned of, naming the key.
TEST(TextureScene, IntegerFormatMismatchesAreErrorsNamingTheKey) {
  const std::vector<std::string> rgba8ui = {"textures.u_tex.internalformat=\"GL_RGBA8UI\"", "textures.u_tex.generate_mipmap=false",
                                            "textures.u_tex.filter=\"nearest\""};
  expect_error(rgba8ui,
               "draws.0.shaders.textures.u_tex.internalformat: GL_RGBA8UI is an integer format, read by "
               "a usampler2D, and the uniform is a sampler2D (GL leaves the result undefined)");
  expect_error({"fragment=\"sampling/lookup_int.frag\""},
               "draws.0.shaders.textures.u_tex.internalformat: the uniform is an isampler2D, which reads "
               "signed integer formats (GL_R8I .. GL_RGBA32I), not GL_RGBA8");
  expect_error(with(rgba8ui, {"fragment=\"sampling/lookup_int.frag\""}),
               "GL_RGBA8UI is an integer format, read by a usampler2D, and the uniform is an isampler2D");
  expect_error({"textures.u_tex.internalformat=\"GL_RGBA8UI\"", "fragment=\"sampling/lookup_uint.frag\""},
               "draws.0.shaders.textures.u_tex.generate_mipmap: glGenerateMipmap refuses an integer format "
               "(GL_RGBA8UI is not filterable");
  // noise_64x64.png's top-left texel is (139, ...): beyond GL_RGBA8I's 127.
  const std::string range = error_of({"textures.u_tex.internalformat=\"GL_RGBA8I\"", "textures.u_tex.generate_mipmap=false",
                                      "textures.u_tex.filter=\"nearest\"", "fragment=\"sampling/lookup_int.frag\""});
  EXPECT_NE(range.find("/tests/data/draws/sampling/noise_64x64.png pixel ("), std::string::npos) << range;
  EXPECT_NE(range.find(", and GL_RGBA8I holds whole numbers from -128 to 127 (internalformat"), std::string::npos) << range;
  // noise_64x64.exr holds k * 6.1 - 3: not whole numbers.
  expect_error({"textures.u_tex.path=\"sampling/noise_64x64.exr\"", "textures.u_tex.internalformat=\"GL_RGBA32I\"",
               "textures.u_tex.generate_mipmap=false", "textures.u_tex.filter=\"nearest\"",
               "fragment=\"sampling/lookup_int.frag\""},
               ", and GL_RGBA32I holds whole numbers from -2147483648 to 2147483647");
  expect_error(with(with(rgba8ui, {"fragment=\"sampling/lookup_uint.frag\""}),
               {"textures.u_tex.border_color=[1, 1.5, 0, 0]"}),
               "draws.0.shaders.textures.u_tex.border_color.1: GL_RGBA8UI is an integer format: expected a whole "
               "number from 0 to 4294967295, got a number (1.5)");
  expect_error(with(with(rgba8ui, {"fragment=\"sampling/lookup_uint.frag\""}),
               {"textures.u_tex.border_color=[-1, 0, 0, 0]"}),
               "border_color.0: GL_RGBA8UI is an integer format: expected a whole number from 0 to 4294967295, got a number (-1)");
  // GL_LINEAR magnification: incomplete, reading the integers (0, 0, 0, 1).
  const RenderResult linear = render_sweep({"textures.u_tex.internalformat=\"GL_RGBA8UI\"", "textures.u_tex.generate_mipmap=false",
                                            "textures.u_tex.min_filter=\"nearest\"", "fragment=\"sampling/lookup_uint.frag\""});
  ASSERT_EQ(linear.stats.warnings.size(), 1u);
  EXPECT_NE(linear.stats.warnings[0].find("the texture is incomplete, so it reads (0, 0, 0, 1): GL_RGBA8UI is an integer "
                                          "format, which GL samples only with GL_NEAREST magnification"),
            std::string::npos) << linear.stats.warnings[0];
  // lookup_uint.frag writes the integers' bits: (0, 0, 0, 1) as integers (GL 4.6 11.1.3.5).
  const glm::vec4 zero_zero_zero_one(0.0f, 0.0f, 0.0f, std::bit_cast<float>(1u));
  for (const glm::vec4& c : linear.framebuffer.color) ASSERT_EQ(std::memcmp(&c, &zero_zero_zero_one, sizeof c), 0);
}

// GL 4.6 8.14.2: with the minification filter GL_NEAREST only the base level is read, for an
// integer format too, whatever levels the texture has and whatever the LOD.
TEST(TextureLod, IntegerNearestMinificationReadsTheBaseLevel) {
  texture::Texture t;
  t.format = texture::TexelFormat::kR32I;
  const std::int64_t level0[4 * 4] = {-7, 0, 0, 1, -7, 0, 0, 1, -7, 0, 0, 1, -7, 0, 0, 1};
  const std::int64_t level1[4] = {123456789, 0, 0, 1};
  t.levels.push_back(texture::make_integer_level(t.format, 2, 2, level0));
  t.levels.push_back(texture::make_integer_level(t.format, 1, 1, level1));
  t.sampler.min_filter = t.sampler.mag_filter = texture::Filter::Nearest;
  t.finalize();
  ASSERT_TRUE(t.complete) << t.incomplete_reason;
  for (float lod : {0.0f, 1.0f, 4.0f}) {
    texture::LodInput in;
    in.lod = lod;
    float out[4];
    texture::sample(t, {0.5f, 0.5f}, in, nullptr, out);
    EXPECT_EQ(std::bit_cast<std::int32_t>(out[0]), -7) << "LOD " << lod;
    EXPECT_EQ(std::bit_cast<std::int32_t>(out[3]), 1) << "LOD " << lod;  // R32I has no alpha: the integer 1
  }
  t.sampler.min_filter = texture::Filter::NearestMipmapNearest;
  t.finalize();
  texture::LodInput in;
  in.lod = 1.0f;
  float out[4];
  texture::sample(t, {0.5f, 0.5f}, in, nullptr, out);
  EXPECT_EQ(std::bit_cast<std::int32_t>(out[0]), 123456789);
}

// Integer texels from files: an 8-bit PNG's stored integers k, a float EXR's whole numbers
// (negative ones for a signed format), stored in the format and read back as the same integers.
TEST(TextureScene, IntegerTexelsAreTheFilesIntegers) {
  const Scene scene = load_scene(kSweep, {"draws.0.shaders.textures.u_tex.internalformat=\"GL_RGBA8UI\"",
                                          "draws.0.shaders.textures.u_tex.generate_mipmap=false"});
  const texture::Texture png = load_texture(scene.draws[0].shaders->textures[0], "png", scene);
  const FloatImage image = read_float_image(std::string(TESSREF_SOURCE_DIR) + "/tests/data/draws/sampling/noise_64x64.png");
  // Texel (x, y) of level 0 is the file's row 63 - y.
  for (int y : {0, 17, 63})
    for (int x : {0, 40, 63})
      for (int c = 0; c < 4; ++c) {
        const float file = image.pixels[std::size_t(((63 - y) * 64 + x) * 4 + c)];
        const float texel = png.levels[0].texels[std::size_t((y * 64 + x) * 4 + c)];
        EXPECT_EQ(std::bit_cast<std::uint32_t>(texel), std::uint32_t(std::lround(file * 255.0f))) << x << ", " << y << ", " << c;
      }
  const std::filesystem::path exr = std::filesystem::temp_directory_path() / "tessref_integers.exr";
  write_float_channels(exr, 2, 1, {"R", "G"}, {-32768.0f, 32767.0f, 0.0f, -1.0f});
  const Scene signed_scene = load_scene(kSweep, {"draws.0.shaders.textures.u_tex.path=\"" + exr.string() + "\"",
                                                 "draws.0.shaders.textures.u_tex.internalformat=\"GL_RG16I\"",
                                                 "draws.0.shaders.textures.u_tex.generate_mipmap=false"});
  const texture::Texture rg16i = load_texture(signed_scene.draws[0].shaders->textures[0], "exr", signed_scene);
  const std::int32_t want[8] = {-32768, 32767, 0, 1, 0, -1, 0, 1};  // missing blue 0, alpha 1
  for (int k = 0; k < 8; ++k) EXPECT_EQ(std::bit_cast<std::int32_t>(rg16i.levels[0].texels[std::size_t(k)]), want[k]) << k;
  EXPECT_EQ(rg16i.levels[0].stored, (std::vector<std::uint8_t>{0x00, 0x80, 0xff, 0x7f, 0x00, 0x00, 0xff, 0xff}));
  std::filesystem::remove(exr);
}

// 2D array textures (GL_TEXTURE_2D_ARRAY): the target, layer files and raw sizes checked by key;
// a sampler whose target is not the texture's refused, as GL draws nothing from it.
TEST(TextureScene, ArrayTexturesAreCheckedByKey) {
  const std::string layers = R"("layers": ["sampling/noise_64x64.png", "sampling/noise_64x64_layer1.png"])";
  auto array = [&](const std::string& keys) {
    return "textures.u_tex={\"path\": null, \"target\": \"GL_TEXTURE_2D_ARRAY\", " + keys + "}";
  };
  expect_error({"textures.u_tex={\"path\": null, " + layers + "}"},
               "draws.0.shaders.textures.u_tex.layers: layers are a 2D array texture's (a 3D texture's slices, a cube "
               "map's faces): give \"target\": \"GL_TEXTURE_2D_ARRAY\", \"GL_TEXTURE_3D\" or \"GL_TEXTURE_CUBE_MAP\"");
  expect_error({"textures.u_tex.target=\"GL_TEXTURE_2D_ARRAY\""},
               "draws.0.shaders.textures.u_tex.path: a GL_TEXTURE_2D_ARRAY's image files are its layers: give "
               "layers (level 0's), or raw bytes of every layer with raw_size [width, height, layers]");
  expect_error({array(R"("layers": ["sampling/noise_64x64.png", "sampling/noise_24x10.png"])")},
               "draws.0.shaders.textures.u_tex.layers.1: " + std::string(TESSREF_SOURCE_DIR) +
               "/tests/data/draws/sampling/noise_24x10.png is 24x10, and layer 0 is 64x64 (an array's layers are one size)");
  expect_error({array(R"("path": "sampling/noise_bytes_0.raw", "internalformat": "GL_RGBA8", "raw_size": [64, 64])")},
               "draws.0.shaders.textures.u_tex.raw_size: expected [width, height, layers], whole numbers from 1 to 16384 "
               "(GL_MAX_TEXTURE_SIZE) and layers from 1 to 2048 (GL_MAX_ARRAY_TEXTURE_LAYERS), got an array of 2");
  expect_error({array(layers)},
               "draws.0.shaders.textures.u_tex.target: the uniform is a sampler2D, which reads a GL_TEXTURE_2D "
               "texture, and this one is GL_TEXTURE_2D_ARRAY");
  expect_error({"fragment=\"sampling/lookup_array.frag\""},
               "draws.0.shaders.textures.u_tex.target: the uniform is a sampler2DArray, which reads a "
               "GL_TEXTURE_2D_ARRAY texture, and this one is GL_TEXTURE_2D");
  // Raw bytes of every layer: four 64 x 64 layers of GL_RGBA8 are noise_bytes_0.raw's 65,536 bytes.
  const Scene scene = load_scene(kSweep, {"draws.0.shaders." + array(R"("path": "sampling/noise_bytes_0.raw", "internalformat": "GL_RGBA8", "raw_size": [64, 64, 4], "generate_mipmap": true)")});
  const texture::Texture t = load_texture(scene.draws[0].shaders->textures[0], "raw", scene);
  ASSERT_EQ(t.levels.size(), 7u);
  EXPECT_TRUE(t.complete) << t.incomplete_reason;
  EXPECT_EQ(t.levels[0].layers, 4);
  EXPECT_EQ(t.levels[6].layers, 4);  // every level has the base level's layers
  EXPECT_EQ(t.levels[0].slice(3).stored - t.levels[0].stored.data(), 3 * 64 * 64 * 4);
}

// GL 4.6 8.14.2: an array's layer is clamp(floor(r + 0.5), 0, d - 1): ties go up (llvmpipe rounds
// them to even), NaN reads layer 0.
TEST(TextureLod, ArrayLayerIsFloorOfRPlusOneHalfClamped) {
  texture::Texture t;
  t.target = texture::Target::k2DArray;
  const std::vector<float> rgba(std::size_t(2 * 2 * 4 * 4), 0.5f);
  t.levels.push_back(texture::make_level(texture::TexelFormat::kRgba8, 2, 2, rgba.data(), 4));
  t.sampler.min_filter = texture::Filter::Nearest;
  t.finalize();
  ASSERT_TRUE(t.complete) << t.incomplete_reason;
  const std::pair<float, int> cases[] = {{0.5f, 1},      {1.5f, 2},     {2.5f, 3},        {0.49999997f, 0}, {-0.5f, 0},
                                         {-0.50000006f, 0}, {3.5f, 3}, {1e30f, 3},       {-INFINITY, 0},   {NAN, 0},
                                         {2.4999998f, 2}};
  for (const auto& [r, layer] : cases) EXPECT_EQ(texture::array_layer(t, r), layer) << r;
}

TEST(TextureScene, LookupsDoNotDependOnThreadsOrBatchSize) {
  // Filters that differ for minification and magnification: the lanes of one sampling vector
  // (two quads) decide together, so runs must not split them.
  for (int fn : {0, 2}) {
    const std::vector<std::string> base = {"uniforms.u_function=" + std::to_string(fn), "textures.u_tex.mag_filter=\"nearest\"",
                                           "textures.u_tex.wrap=\"mirrored_repeat\""};
    const std::vector<glm::vec4> reference = render_sweep(base, 1).framebuffer.color;
    for (int lanes : {4, 12, 256}) {
      std::vector<std::string> sets = base;
      sets.push_back("batch_lanes=" + std::to_string(lanes));
      const std::vector<glm::vec4> color = render_sweep(sets, 2).framebuffer.color;
      ASSERT_EQ(color.size(), reference.size());
      EXPECT_EQ(std::memcmp(color.data(), reference.data(), color.size() * sizeof(glm::vec4)), 0)
          << "function " << fn << ", " << lanes << " lanes";
    }
  }
}

// glGenerateMipmap on an odd size: a two-tap sample at each new texel's centre (Mesa's blit), in
// 8-bit fixed point for GL_RGBA8: a 5-texel row 0, 64, 128, 192, 255 becomes two texels, the first
// from texels 0 and 1 with weight 192/256 on texel 1, the second from texels 3 and 4 with weight
// 64/256 on texel 4; texel 2 is not read.
TEST(TextureMipmap, OddSizesAreBilinearAtTheNewTexelCentres) {
  texture::Texture t;
  t.format = texture::TexelFormat::kRgba8;
  const float row[5] = {0.0f, 64.0f / 255.0f, 128.0f / 255.0f, 192.0f / 255.0f, 1.0f};
  std::vector<float> rgba;
  for (float v : row) rgba.insert(rgba.end(), {v, v, v, 1.0f});
  t.levels.push_back(texture::make_level(t.format, 5, 1, rgba.data()));
  texture::generate_mipmaps(t);
  ASSERT_EQ(t.levels.size(), 3u);
  ASSERT_EQ(t.levels[1].width, 2);
  // 0 + ((192 * 64 + 128) >> 8) = 48; 192 + ((64 * 63 + 128) >> 8) = 208 (a box filter: 32 and 224).
  EXPECT_EQ(t.levels[1].stored[0], 48);
  EXPECT_EQ(t.levels[1].stored[4], 208);
  EXPECT_TRUE(t.complete);
  EXPECT_EQ(t.last_level, 2);
}

// Level 1 of a GL_RGBA32F ramp (texel (i, j) holds (i, j)) as llvmpipe's glGenerateMipmap makes it,
// read back from Mesa 22.3.6 (glGetTexImage): a linear lookup of a ramp returns its coordinate in
// texels, so each value is where llvmpipe's blit sampled, a few ulps off the texel centre where
// the size is not a power of two, and different on each side of the blit's diagonal.
TEST(TextureMipmap, GeneratedLevelsSampleWhereLlvmpipesBlitDoes) {
  struct Case {
    int w, h, x, y;
    float s, t;  // level 1's texel (x, y): its red and green
  };
  const Case cases[] = {
      {24, 10, 0, 0, 0x1.ffffcp-2f, 0x1.ffffcp-2f},  {24, 10, 6, 0, 0x1.8ffffep+3f, 0x1.000004p-1f},
      {24, 10, 3, 2, 0x1.9ffffcp+2f, 0x1.1ffffep+2f}, {24, 10, 11, 4, 0x1.68p+4f, 0x1.100002p+3f},
      {7, 3, 0, 0, 0x1.55554cp-1f, 1.0f},             {7, 3, 1, 0, 0x1.7ffffep+1f, 1.0f},
      {7, 3, 2, 0, 0x1.555554p+2f, 1.0f},             {100, 7, 0, 0, 0x1.0000a8p-1f, 0x1.55554cp-1f},
      {100, 7, 49, 0, 0x1.8ap+6f, 0x1.555558p-1f},    {100, 7, 49, 2, 0x1.8ap+6f, 0x1.555556p+2f},
  };
  for (const Case& c : cases) {
    texture::Texture t;
    std::vector<float> rgba;
    for (int j = 0; j < c.h; ++j)
      for (int i = 0; i < c.w; ++i) rgba.insert(rgba.end(), {float(i), float(j), 0.0f, 1.0f});
    t.levels.push_back(texture::make_level(texture::TexelFormat::kRgba32F, c.w, c.h, rgba.data()));
    texture::generate_mipmaps(t);
    const texture::Level& l = t.levels[1];
    const float* texel = l.texels.data() + (std::size_t(c.y) * std::size_t(l.width) + std::size_t(c.x)) * 4;
    EXPECT_EQ(texel[0], c.s) << c.w << "x" << c.h << " (" << c.x << ", " << c.y << ")";
    EXPECT_EQ(texel[1], c.t) << c.w << "x" << c.h << " (" << c.x << ", " << c.y << ")";
  }
}

// textureQueryLod's LOD is llvmpipe's 0.5 * fastlog2(ρ²): exact at powers of two, linear between.
TEST(TextureLod, FastLog2IsExactAtPowersOfTwoAndLinearBetween) {
  texture::Texture t;
  std::vector<float> rgba(64 * 64 * 4, 0.5f);
  t.levels.push_back(texture::make_level(texture::TexelFormat::kRgba32F, 64, 64, rgba.data()));
  texture::generate_mipmaps(t);
  t.sampler.min_filter = texture::Filter::LinearMipmapLinear;
  t.finalize();
  auto lod = [&](float step) {
    texture::LodInput in;
    in.from = texture::LodInput::From::Derivatives;
    in.dsdx = step / 64.0f;
    in.dtdy = step / 64.0f;
    float out[2];
    texture::query_lod(t, in, out);
    return out[1];
  };
  EXPECT_EQ(lod(4.0f), 2.0f);
  EXPECT_EQ(lod(1.5f), 0.5625f);  // log2(1.5) is 0.585
  EXPECT_EQ(lod(0.0f), -63.5f);
}

TEST(TextureScene, OneDimensionalAndBufferTexturesAreCheckedByKey) {
  auto one_d = [](const std::string& target, const std::string& keys) {
    return "textures.u_tex={\"path\": null, \"target\": \"" + target + "\", " + keys + "}";
  };
  // A 1D level is one row; a 1D array's layers are its image's rows; raw sizes per target.
  expect_error({one_d("GL_TEXTURE_1D", R"("path": "sampling/noise_24x10.png")"), "fragment=\"sampling/lookup_1d.frag\""},
               "draws.0.shaders.textures.u_tex: " + std::string(TESSREF_SOURCE_DIR) +
                   "/tests/data/draws/sampling/noise_24x10.png is 24x10, and a GL_TEXTURE_1D level is one row (an image of "
                   "height 1)");
  expect_error({one_d("GL_TEXTURE_1D_ARRAY", R"("layers": ["sampling/noise_1d_256.png"])")},
               "draws.0.shaders.textures.u_tex.layers: layers are a 2D array texture's (a 3D texture's slices, a cube "
               "map's faces): give \"target\": \"GL_TEXTURE_2D_ARRAY\", \"GL_TEXTURE_3D\" or \"GL_TEXTURE_CUBE_MAP\" (a 1D "
               "array's layers are the rows of its path or levels images)");
  expect_error({one_d("GL_TEXTURE_1D", R"("path": "sampling/depth_1d_256.raw", "internalformat": "GL_R32F", "raw_size": [256, 1])")},
               "draws.0.shaders.textures.u_tex.raw_size: expected [width], whole numbers from 1 to 16384 "
               "(GL_MAX_TEXTURE_SIZE), got an array of 2");
  expect_error({one_d("GL_TEXTURE_1D_ARRAY", R"("levels": ["sampling/noise_1d_array_64x5.png", "sampling/noise_1d_256.png"])"),
                "textures.u_tex.generate_mipmap=false"},
               "draws.0.shaders.textures.u_tex.levels.1: level 1 is 256x1, and a level 1 of a 64x5 texture is 32x5 (a 1D "
               "array's rows are its layers, in every level)");
  expect_error({one_d("GL_TEXTURE_1D", R"("path": "sampling/noise_1d_256.png")")},
               "draws.0.shaders.textures.u_tex.target: the uniform is a sampler2D, which reads a GL_TEXTURE_2D texture, "
               "and this one is GL_TEXTURE_1D");
  expect_error({"textures.u_tex.target=\"GL_TEXTURE_2D_MULTISAMPLE\""},
               "draws.0.shaders.textures.u_tex.target: expected one of GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, "
               "GL_TEXTURE_RECTANGLE, GL_TEXTURE_1D_ARRAY, GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BUFFER, GL_TEXTURE_CUBE_MAP, "
               "GL_TEXTURE_CUBE_MAP_ARRAY, got \"GL_TEXTURE_2D_MULTISAMPLE\"");
  // Buffer textures: a range of a scene buffer in a format of GL 4.6 table 8.18, no sampler state.
  auto buffer = [](const std::string& keys) {
    return std::vector<std::string>{"textures.u_tex={\"path\": null, \"generate_mipmap\": null, \"min_filter\": null, "
                                    "\"mag_filter\": null, \"wrap\": null, \"target\": \"GL_TEXTURE_BUFFER\", " + keys + "}",
                                    "fragment=\"sampling/lookup_buffer.frag\"", "uniforms={\"u_size_lod\": null, \"u_count\": 4}"};
  };
  expect_error(buffer(R"("buffer": "noise_bytes", "internalformat": "GL_RGB8")"),
               "draws.0.shaders.textures.u_tex.internalformat: GL_RGB8 is not a buffer texture format (GL 4.6 table 8.18)");
  expect_error(buffer(R"("buffer": "noise_bytes", "internalformat": null)"),
               "draws.0.shaders.textures.u_tex.internalformat: a GL_TEXTURE_BUFFER needs the format its bytes hold");
  expect_error(buffer(R"("buffer": "nothing", "internalformat": "GL_R8")"),
               "draws.0.shaders.textures.u_tex.buffer: no buffer named \"nothing\" (buffers: corners, noise_bytes, "
               "noise_floats, noise_halfs)");
  expect_error(buffer(R"("buffer": "noise_bytes", "internalformat": "GL_R8", "offset": 100)"),
               "draws.0.shaders.textures.u_tex.offset: 100 is not a multiple of 256");
  expect_error(buffer(R"("buffer": "noise_bytes", "internalformat": "GL_R8", "offset": 65280, "size": 512)"),
               "draws.0.shaders.textures.u_tex.size: offset 65280 + size 512 is past the buffer's end: "
               "buffers.noise_bytes has 65536 bytes");
  expect_error(buffer(R"("buffer": "noise_bytes", "internalformat": "GL_R8", "offset": 65536)"),
               "draws.0.shaders.textures.u_tex.offset: 65536 is not inside the buffer: buffers.noise_bytes has 65536 bytes");
  expect_error(buffer(R"("buffer": "noise_bytes", "internalformat": "GL_R8", "wrap": "repeat")"),
               "draws.0.shaders.textures.u_tex.wrap: a GL_TEXTURE_BUFFER texture has no images, levels or sampler state");
  expect_error(buffer(R"("buffer": "noise_bytes", "internalformat": "GL_R8UI")"),
               "draws.0.shaders.textures.u_tex.internalformat: GL_R8UI is an integer format, read by a usamplerBuffer, "
               "and the uniform is a samplerBuffer");
}

// A buffer texture's texels are its range's whole texels, from the buffer's own bytes: GL_RG16
// over bytes 256 .. 256 + 4003 of noise_bytes_0.raw is 1000 texels, texel k from bytes 256 + 4k.
TEST(TextureScene, BufferTextureTexelsAreTheRangesWholeTexels) {
  const Scene scene = load_scene(kSweep, {"draws.0.shaders.textures.u_tex={\"path\": null, \"generate_mipmap\": null, "
                                          "\"min_filter\": null, \"mag_filter\": null, \"wrap\": null, \"target\": "
                                          "\"GL_TEXTURE_BUFFER\", \"buffer\": \"noise_bytes\", \"internalformat\": \"GL_RG16\", "
                                          "\"offset\": 256, \"size\": 4003}"});
  const texture::Texture t = load_texture(scene.draws[0].shaders->textures[0], "buffer", scene);
  ASSERT_TRUE(t.complete);
  int size[3];
  texture::level_size(t, 5, size);  // a buffer texture has no levels: the lod is ignored
  EXPECT_EQ(size[0], 1000);
  std::ifstream in(std::string(TESSREF_SOURCE_DIR) + "/tests/data/draws/sampling/noise_bytes_0.raw", std::ios::binary);
  std::vector<unsigned char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  for (int k : {0, 1, 999}) {
    float texel[4];
    texture::fetch(t, k, 0, 0, 0, texel);
    const std::size_t at = 256 + 4 * std::size_t(k);
    EXPECT_EQ(texel[0], float(bytes[at] | bytes[at + 1] << 8) / 65535.0f) << k;
    EXPECT_EQ(texel[1], float(bytes[at + 2] | bytes[at + 3] << 8) / 65535.0f) << k;
    EXPECT_EQ(texel[2], 0.0f);
    EXPECT_EQ(texel[3], 1.0f);
  }
  float outside[4];
  texture::fetch(t, 1000, 0, 0, 0, outside);  // past the range: zeros, alpha 1 for a format without alpha
  EXPECT_EQ(outside[0], 0.0f);
  EXPECT_EQ(outside[1], 0.0f);
  EXPECT_EQ(outside[3], 1.0f);
}

// A 1D texture's LOD is log2(ρ) with ρ = max(|ds/dx|, |ds/dy|) · w (GL 4.6 8.14.1 with one
// coordinate); its 1D array's layer is the second coordinate's.
TEST(TextureLod, OneDimensionalLodUsesSAlone) {
  texture::Texture t;
  t.target = texture::Target::k1D;
  std::vector<float> rgba(256 * 4, 0.25f);
  t.levels.push_back(texture::make_level(texture::TexelFormat::kRgba32F, 256, 1, rgba.data()));
  texture::generate_mipmaps(t);
  t.sampler.min_filter = texture::Filter::LinearMipmapLinear;
  t.finalize();
  ASSERT_TRUE(t.complete) << t.incomplete_reason;
  EXPECT_EQ(t.last_level, 8);
  auto lod = [&](float dsdx, float dsdy) {
    texture::LodInput in;
    in.from = texture::LodInput::From::Derivatives;
    in.dsdx = dsdx;
    in.dsdy = dsdy;
    in.dtdx = 1.0f;  // t is not a 1D texture's: ignored
    float out[2];
    texture::query_lod(t, in, out);
    return out[1];
  };
  EXPECT_EQ(lod(4.0f / 256.0f, 0.0f), 2.0f);
  EXPECT_EQ(lod(-1.0f / 256.0f, 8.0f / 256.0f), 3.0f);
  EXPECT_EQ(lod(1.5f / 256.0f, 0.0f), 0.5625f);
  int size[3];
  texture::level_size(t, 2, size);
  EXPECT_EQ(size[0], 64);
}

// A 3D texture's level 0 is one image per depth slice (or raw bytes of every slice); its depth
// halves with each level, as GL 4.6 8.17's level sizes say, and textureSize gives all three.
TEST(TextureScene, ThreeDimensionalTexturesHalveTheirDepth) {
  const std::string slices = R"("layers": ["sampling/noise_64x64.png", "sampling/noise_64x64_layer1.png", )"
                             R"("sampling/noise_64x64_layer2.png", "sampling/noise_64x64_layer3.png"])";
  auto three_d = [](const std::string& keys) {
    return "textures.u_tex={\"path\": null, \"target\": \"GL_TEXTURE_3D\", " + keys + "}";
  };
  expect_error({three_d(R"("path": "sampling/noise_64x64.png")")},
               "draws.0.shaders.textures.u_tex.path: a GL_TEXTURE_3D's image files are its depth slices: give layers");
  expect_error({three_d(R"("path": "sampling/noise_bytes_0.raw", "internalformat": "GL_RGBA8", "raw_size": [64, 64, 4000])")},
               "draws.0.shaders.textures.u_tex.raw_size: expected [width, height, depth], whole numbers from 1 to 2048 "
               "(GL_MAX_3D_TEXTURE_SIZE)");
  expect_error({three_d(slices)},
               "draws.0.shaders.textures.u_tex.target: the uniform is a sampler2D, which reads a GL_TEXTURE_2D texture, "
               "and this one is GL_TEXTURE_3D");
  const Scene scene = load_scene(kSweep, {"draws.0.shaders." + three_d(slices)});
  const texture::Texture t = load_texture(scene.draws[0].shaders->textures[0], "3d", scene);
  ASSERT_TRUE(t.complete) << t.incomplete_reason;
  ASSERT_EQ(t.levels.size(), 7u);  // 64 x 64 x 4 down to 1 x 1 x 1
  const int depths[] = {4, 2, 1, 1, 1, 1, 1};
  for (std::size_t k = 0; k < 7; ++k) EXPECT_EQ(t.levels[k].layers, depths[k]) << k;
  int size[3];
  texture::level_size(t, 1, size);
  EXPECT_EQ(size[0], 32);
  EXPECT_EQ(size[1], 32);
  EXPECT_EQ(size[2], 2);
  // Level 1's slice 0 is the mean of the 2 x 2 x 2 block below it in 8-bit fixed point: three
  // interpolations (s, t, r), each rounding to 8 bits, keep it within 1.5 steps of the exact mean
  // of slices 0 and 1's texels (0, 0) to (1, 1).
  int sum = 0;
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x) sum += t.levels[0].slice(z).stored[std::size_t(y * 64 + x) * 4];
  EXPECT_NEAR(t.levels[1].stored[0], sum / 8.0, 1.5);
}

// A rectangle texture takes what glTexParameter allows it, each refusal naming the key.
TEST(TextureScene, RectangleTexturesAreCheckedByKey) {
  auto rect = [](const std::string& keys) {
    return std::vector<std::string>{"textures.u_tex={\"target\": \"GL_TEXTURE_RECTANGLE\", \"generate_mipmap\": false, "
                                    "\"min_filter\": \"linear\", \"wrap\": \"clamp_to_edge\"" + keys + "}",
                                    "fragment=\"sampling/lookup_rect.frag\"", "uniforms={\"u_size_lod\": null}"};
  };
  EXPECT_EQ(error_of(rect("")), "no error");
  expect_error(rect(R"(, "generate_mipmap": true)"),
               "draws.0.shaders.textures.u_tex.generate_mipmap: a GL_TEXTURE_RECTANGLE has level 0 alone");
  expect_error(rect(R"(, "min_filter": "linear_mipmap_linear")"),
               "draws.0.shaders.textures.u_tex.min_filter: a GL_TEXTURE_RECTANGLE is sampled with nearest or linear only, "
               "not GL_LINEAR_MIPMAP_LINEAR");
  expect_error(rect(R"(, "wrap_t": "repeat")"),
               "draws.0.shaders.textures.u_tex.wrap_t: a GL_TEXTURE_RECTANGLE wraps with clamp_to_edge (its default) or "
               "clamp_to_border only");
  expect_error(rect(R"(, "base_level": 1)"),
               "draws.0.shaders.textures.u_tex.base_level: a GL_TEXTURE_RECTANGLE has level 0 alone (GL_TEXTURE_BASE_LEVEL "
               "other than 0: GL_INVALID_OPERATION)");
  expect_error(rect(R"(, "sampler": {"min_filter": "nearest"})"),
               "draws.0.shaders.textures.u_tex.sampler: on a GL_TEXTURE_RECTANGLE, tessref takes a sampler object");
  // GL_TEXTURE_MAX_ANISOTROPY: 1 is GL's isotropic default; above it refused by name, below it GL's error.
  EXPECT_EQ(error_of(rect(R"(, "max_anisotropy": 1)")), "no error");
  expect_error(rect(R"(, "max_anisotropy": 16)"),
               "draws.0.shaders.textures.u_tex.max_anisotropy: tessref does not filter anisotropically "
               "(GL_TEXTURE_MAX_ANISOTROPY 16); llvmpipe does");
  expect_error(rect(R"(, "sampler": {"min_filter": "linear", "wrap": "clamp_to_edge", "max_anisotropy": 0.5})"),
               "draws.0.shaders.textures.u_tex.sampler.max_anisotropy: GL_TEXTURE_MAX_ANISOTROPY below 1 is GL_INVALID_VALUE");
  // Its default wrap is GL's clamp_to_edge, not the scene's repeat.
  const Scene scene = load_scene(kSweep, {"draws.0.shaders.textures.u_tex={\"target\": \"GL_TEXTURE_RECTANGLE\", "
                                          "\"generate_mipmap\": false, \"min_filter\": \"linear\", \"wrap\": null}"});
  const TextureSetting& t = scene.draws[0].shaders->textures[0];
  EXPECT_EQ(t.sampler_state.wrap_s, texture::Wrap::ClampToEdge);
  EXPECT_EQ(t.sampler_state.wrap_t, texture::Wrap::ClampToEdge);
}

}  // namespace
}  // namespace tessref
