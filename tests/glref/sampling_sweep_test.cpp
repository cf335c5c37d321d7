// The sampling sweep (issue 20): one texture lookup per pixel, written as returned to a
// GL_RGBA32F draw buffer, drawn by tessref and by llvmpipe from the same scene
// (tests/data/draws/sampling_sweep.json) for textures of several formats and sizes, every filter,
// wrap mode and lookup function, and sampler state. Each case is 16,384 lookups at dyadic
// coordinates (lookup.frag): random, at texture edges, texel edges and centres, LODs from -2 past
// the last level, ties at .5. Compared bit for bit; where tessref's arithmetic is knowingly not
// llvmpipe's, the differences are counted against a stated bound.
//
// TESSREF_SAMPLING_SWEEP=full runs every format x minification x magnification filter x wrap
// x lookup, and every depth format x filter x wrap x shadow lookup (scripts/sampling-sweep.sh);
// TESSREF_SAMPLING_SWEEP_MATCH=TEXT runs the cases whose keys contain TEXT.
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gl_fixture.h"
#include "glref/scene_renderer.h"
#include "mesh/mesh_source.h"
#include "render/render.h"
#include "scene/scene_loader.h"
#include "texture/texel_format.h"

namespace tessref::glref {
namespace {

const std::string kScene = std::string(TESSREF_SOURCE_DIR) + "/tests/data/draws/sampling_sweep.json";


struct Outcome {
  std::size_t lookups = 0, identical = 0;
  std::size_t beyond = 0;       // lookups with a channel further than the case's tolerance
  float max_difference = 0.0f;  // over channels that differ (NaN against a number: infinity)
  std::string first;            // the first difference, for the failure message
};

// Draws both with `sets` (keys under draws.0.shaders, or under draws.0 when they begin with
// "draw.") and compares draw buffer 0 bit for bit.
Outcome compare(GlContext& ctx, const std::vector<std::string>& sets, float tolerance) {
  std::vector<std::string> full;
  for (const std::string& s : sets)
    full.push_back(s.starts_with("draw.") ? "draws.0." + s.substr(5) : "draws.0.shaders." + s);
  const Scene scene = load_scene(kScene, full);
  std::vector<std::string> warnings;
  const Mesh mesh = build_mesh(scene.mesh, warnings);
  const RenderResult ours = render_scene(scene, mesh, Parallel());
  SceneRenderer renderer(ctx, scene, mesh);
  const Framebuffer gl = renderer.render();
  Outcome o;
  for (std::size_t i = 0; i < gl.color.size(); ++i) {
    ++o.lookups;
    bool same = true, beyond = false;
    for (int c = 0; c < 4; ++c) {
      const float a = ours.framebuffer.color[i][c], b = gl.color[i][c];
      if (std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b)) continue;
      same = false;
      const float d = std::isnan(a) != std::isnan(b) ? INFINITY : std::fabs(a - b);
      o.max_difference = std::max(o.max_difference, d);
      beyond = beyond || !(d <= tolerance);
      if (o.first.empty()) {
        char buf[512];
        const glm::vec4 &t = ours.framebuffer.color[i], &l = gl.color[i];
        std::snprintf(buf, sizeof buf,
                      "pixel (%zu, %zu) channel %d: tessref %.9g (0x%08x), llvmpipe %.9g (0x%08x); all four: tessref "
                      "0x%08x 0x%08x 0x%08x 0x%08x, llvmpipe 0x%08x 0x%08x 0x%08x 0x%08x",
                      i % std::size_t(gl.width), i / std::size_t(gl.width), c, double(a), std::bit_cast<std::uint32_t>(a),
                      double(b), std::bit_cast<std::uint32_t>(b), std::bit_cast<std::uint32_t>(t.x),
                      std::bit_cast<std::uint32_t>(t.y), std::bit_cast<std::uint32_t>(t.z), std::bit_cast<std::uint32_t>(t.w),
                      std::bit_cast<std::uint32_t>(l.x), std::bit_cast<std::uint32_t>(l.y), std::bit_cast<std::uint32_t>(l.z),
                      std::bit_cast<std::uint32_t>(l.w));
        o.first = buf;
      }
    }
    o.identical += same;
    o.beyond += beyond;
  }
  return o;
}

std::string joined(const std::vector<std::string>& sets) {
  std::string out;
  for (const std::string& s : sets) out += (out.empty() ? "" : " ") + s;
  return out;
}

// What a case must show: bit-exact, or within a bound stated with its reason.
struct Case {
  std::vector<std::string> sets;
  // sRGB textures with glGenerateMipmap: llvmpipe encodes each generated level with an
  // approximation built on the CPU's rsqrtps, whose bits differ between x86 vendors, so tessref
  // encodes by GL's equation; a generated texel can then be one 8-bit step away, and a lookup by
  // at most the largest step of the decoded scale (0.0089, at k = 254).
  float tolerance = 0.0f;  // 0: bit-exact
  // The share of lookups that may differ beyond the tolerance, where a case says why.
  double max_differing = 0.0;
};

// A texture's keys: file, format, mipmaps, filters and wraps.
std::vector<std::string> texture(const std::string& file, const std::string& format, const std::string& min_filter,
                                 const std::string& mag_filter, const std::string& wrap) {
  return {"textures.u_tex.path=\"sampling/" + file + "\"", "textures.u_tex.internalformat=\"" + format + "\"",
          "textures.u_tex.min_filter=\"" + min_filter + "\"", "textures.u_tex.mag_filter=\"" + mag_filter + "\"",
          "textures.u_tex.wrap=\"" + wrap + "\""};
}

std::vector<std::string> with(std::vector<std::string> sets, const std::vector<std::string>& more) {
  sets.insert(sets.end(), more.begin(), more.end());
  return sets;
}

std::string function(int f) { return "uniforms.u_function=" + std::to_string(f); }

bool linear_image(const std::string& filter) { return filter.rfind("linear", 0) == 0; }

// A case and what it must show (Case): bit-exact unless an sRGB format's generated levels apply.
// Filters that differ for minification and magnification are bit-exact too: llvmpipe filters the
// GL_NEAREST lanes of a vector of two quads by the GL_LINEAR ones (texture::linear_in_vector), and
// the rasterizer hands tessref's fragment stage the same vectors, an uncovered quad as helpers.
Case make_case(const std::string& file, const std::string& format, const std::string& min, const std::string& mag,
               const std::string& wrap, int fn, const std::vector<std::string>& extra = {}) {
  Case c{with(with(texture(file, format, min, mag, wrap), {function(fn)}), extra)};
  if (format.find("SRGB") != std::string::npos) c.tolerance = 0.0089f;
  return c;
}

// A shadow lookup (lookup_shadow.frag, function fn) on depth_64x64.exr stored in a depth format,
// compared by `func`. Depth formats have no glGenerateMipmap, so the filters are mipmap-free.
Case shadow_case(const std::string& format, const std::string& min, const std::string& mag, const std::string& wrap,
                 const std::string& func, int fn, const std::vector<std::string>& extra = {}) {
  Case c{with(texture("depth_64x64.exr", format, min, mag, wrap),
              {"textures.u_tex.generate_mipmap=false", "fragment=\"sampling/lookup_shadow.frag\"",
               "textures.u_tex.compare_mode=\"compare_ref_to_texture\"", "textures.u_tex.compare_func=\"" + func + "\"",
               function(fn)})};
  c.sets = with(c.sets, extra);
  return c;
}

// The integer formats (GL 4.6 table 8.12) read by an isampler2D or usampler2D (lookup_int.frag,
// lookup_uint.frag), from raw random bytes (every bit pattern is a value) given as six levels with
// GL_TEXTURE_MAX_LEVEL 5: GL samples them with GL_NEAREST only, so these are exact copies. With
// the minification filter GL_NEAREST the texture has level 0 alone: Mesa samples an integer
// texture's levels as GL_NEAREST_MIPMAP_NEAREST then, where GL reads the base level
// (docs/textures.md), and with one level both read it.
struct IntegerFormat {
  const char* name;
  int width, height;  // level 0, so that its bytes are the chain's level 0 file
  bool rgb;           // noise_bytes3_*.raw (texels of 3, 6 or 12 bytes), else noise_bytes_*.raw
};
const IntegerFormat kIntegerFormats[] = {
    {"GL_RGBA32I", 64, 64, false},   {"GL_RGBA32UI", 64, 64, false},  {"GL_RGBA16I", 128, 64, false},
    {"GL_RGBA16UI", 128, 64, false}, {"GL_RG32I", 128, 64, false},    {"GL_RG32UI", 128, 64, false},
    {"GL_RGBA8I", 128, 128, false},  {"GL_RGBA8UI", 128, 128, false}, {"GL_RG16I", 128, 128, false},
    {"GL_RG16UI", 128, 128, false},  {"GL_R32I", 128, 128, false},    {"GL_R32UI", 128, 128, false},
    {"GL_RGB10_A2UI", 128, 128, false}, {"GL_RG8I", 256, 128, false}, {"GL_RG8UI", 256, 128, false},
    {"GL_R16I", 256, 128, false},    {"GL_R16UI", 256, 128, false},   {"GL_R8I", 256, 256, false},
    {"GL_R8UI", 256, 256, false},    {"GL_RGB32I", 64, 64, true},     {"GL_RGB32UI", 64, 64, true},
    {"GL_RGB16I", 128, 64, true},    {"GL_RGB16UI", 128, 64, true},   {"GL_RGB8I", 128, 128, true},
    {"GL_RGB8UI", 128, 128, true}};

// The raw chain's files, noise_bytes_*.raw or noise_bytes3_*.raw, as a JSON list: levels 0 to 5, or
// level 0 alone with the minification filter GL_NEAREST (see above).
std::string raw_levels(bool rgb, const std::string& min) {
  std::string levels;
  for (int k = 0; k < (min == "nearest" ? 1 : 6); ++k)
    levels += std::string(k ? ", " : "") + "\"sampling/noise_bytes" + (rgb ? "3" : "") + "_" + std::to_string(k) + ".raw\"";
  return "[" + levels + "]";
}

Case integer_case(const IntegerFormat& f, const std::string& min, const std::string& mag, const std::string& wrap, int fn,
                  const std::string& extra = "") {
  const bool is_unsigned = std::string(f.name).find("UI") != std::string::npos;
  return Case{{"fragment=\"sampling/lookup_" + std::string(is_unsigned ? "uint" : "int") + ".frag\"",
               "textures.u_tex={\"path\": null, \"levels\": " + raw_levels(f.rgb, min) + ", \"raw_size\": [" + std::to_string(f.width) +
                   ", " + std::to_string(f.height) + "], \"internalformat\": \"" + f.name +
                   "\", \"generate_mipmap\": false, \"max_level\": 5, \"min_filter\": \"" + min + "\", \"mag_filter\": \"" +
                   mag + "\", \"wrap\": \"" + wrap + "\"" + extra + "}",
               function(fn)}};
}

// A 2D array texture (lookup_array.frag) of three 64 x 64 layers with glGenerateMipmap, stored
// in `format`: a layer coordinate per lookup from -2 to 4.875 in eighths, clamped to the layers,
// avoiding ties (see docs/textures.md). What it must show follows make_case.
Case array_case(const std::string& format, const std::string& min, const std::string& mag, const std::string& wrap, int fn) {
  // lookup_array.frag's function 8 is textureGradOffset: a LOD per lookup, as function 3's.
  Case c = make_case("noise_64x64.png", format, min, mag, wrap, fn == 8 ? 3 : fn);
  c.sets = {"fragment=\"sampling/lookup_array.frag\"",
            "textures.u_tex={\"path\": null, \"target\": \"GL_TEXTURE_2D_ARRAY\", \"layers\": [\"sampling/noise_64x64.png\", "
            "\"sampling/noise_64x64_layer1.png\", \"sampling/noise_64x64_layer2.png\"], \"internalformat\": \"" + format +
                "\", \"generate_mipmap\": true, \"min_filter\": \"" + min + "\", \"mag_filter\": \"" + mag + "\", \"wrap\": \"" +
                wrap + "\"}",
            function(fn)};
  return c;
}

// A signed integer 2D array (lookup_int_array.frag) of four 64 x 64 layers of GL_RGBA8I from
// raw random bytes (noise_bytes_*.raw, six levels, GL_TEXTURE_MAX_LEVEL 5).
Case integer_array_case(const std::string& min, const std::string& wrap, int fn) {
  return Case{{"fragment=\"sampling/lookup_int_array.frag\"",
               "textures.u_tex={\"path\": null, \"target\": \"GL_TEXTURE_2D_ARRAY\", \"levels\": " + raw_levels(false, min) +
                   ", \"raw_size\": [64, 64, 4], \"internalformat\": \"GL_RGBA8I\", \"generate_mipmap\": false, "
                   "\"max_level\": 5, \"min_filter\": \"" + min + "\", \"mag_filter\": \"nearest\", \"wrap\": \"" + wrap +
                   "\", \"border_color\": [-300, 5, 127, -128]}",
               function(fn)}};
}

const char* const kDepthFormats[] = {"GL_DEPTH_COMPONENT16", "GL_DEPTH_COMPONENT24", "GL_DEPTH_COMPONENT32F",
                                     "GL_DEPTH24_STENCIL8"};
const char* const kCompareFuncs[] = {"lequal", "gequal", "less", "greater", "equal", "notequal", "always", "never"};

// A shadow lookup on a 2D array of two depth layers (lookup_shadow_array.frag: the lookups GLSL
// has for a sampler2DArrayShadow), as shadow_case.
Case shadow_array_case(const std::string& format, const std::string& min, const std::string& mag, const std::string& wrap,
                       const std::string& func, int fn) {
  Case c = shadow_case(format, min, mag, wrap, func, fn);
  c.sets = {"fragment=\"sampling/lookup_shadow_array.frag\"",
            "textures.u_tex={\"path\": null, \"target\": \"GL_TEXTURE_2D_ARRAY\", \"layers\": [\"sampling/depth_64x64.exr\", "
            "\"sampling/depth_64x64_layer1.exr\"], \"internalformat\": \"" + format + "\", \"generate_mipmap\": false, "
            "\"min_filter\": \"" + min + "\", \"mag_filter\": \"" + mag + "\", \"wrap\": \"" + wrap +
                "\", \"compare_mode\": \"compare_ref_to_texture\", \"compare_func\": \"" + func + "\"}",
            function(fn)};
  return c;
}

// c with more keys.
Case with_sets(Case c, const std::vector<std::string>& more) {
  c.sets = with(c.sets, more);
  return c;
}

// A 1D texture (lookup_1d.frag: function 8 is textureProj, 10 textureGradOffset) of 256 texels with
// glGenerateMipmap, or a 1D array (lookup_1d_array.frag) of five 64-texel layers, stored in
// `format`. What it must show follows make_case.
Case one_d_case(bool array, const std::string& format, const std::string& min, const std::string& mag,
                const std::string& wrap, int fn) {
  // Function 10 has a LOD per lookup, as function 3 (make_case's 10 is a gather); 8 in the
  // array's shader is textureGradOffset, likewise.
  Case c = make_case("noise_1d_256.png", format, min, mag, wrap, fn == 10 || (array && fn == 8) ? 3 : fn);
  c.sets = {std::string("fragment=\"sampling/lookup_1d") + (array ? "_array" : "") + ".frag\"",
            "textures.u_tex={\"path\": \"sampling/" + std::string(array ? "noise_1d_array_64x5.png" : "noise_1d_256.png") +
                "\", \"target\": \"" + (array ? "GL_TEXTURE_1D_ARRAY" : "GL_TEXTURE_1D") + "\", \"internalformat\": \"" + format +
                "\", \"generate_mipmap\": true, \"min_filter\": \"" + min + "\", \"mag_filter\": \"" + mag + "\", \"wrap\": \"" +
                wrap + "\"}",
            function(fn)};
  return c;
}

// A shadow lookup (lookup_1d_shadow.frag) on a 1D depth texture of 256 texels from raw bytes
// (depth_1d_256.raw as GL_DEPTH_COMPONENT32F, depth16_1d_256.raw as GL_DEPTH_COMPONENT16).
Case one_d_shadow_case(const std::string& format, const std::string& min, const std::string& mag, const std::string& wrap,
                       const std::string& func, int fn) {
  Case c = shadow_case(format, min, mag, wrap, func, fn == 6 ? 0 : fn);  // function 6 is textureProj
  const std::string file = format == "GL_DEPTH_COMPONENT16" ? "depth16_1d_256.raw" : "depth_1d_256.raw";
  c.sets = {"fragment=\"sampling/lookup_1d_shadow.frag\"",
            "textures.u_tex={\"path\": \"sampling/" + file + "\", \"target\": \"GL_TEXTURE_1D\", \"raw_size\": [256], "
            "\"internalformat\": \"" + format + "\", \"generate_mipmap\": false, \"min_filter\": \"" + min +
                "\", \"mag_filter\": \"" + mag + "\", \"wrap\": \"" + wrap +
                "\", \"compare_mode\": \"compare_ref_to_texture\", \"compare_func\": \"" + func + "\"}",
            function(fn)};
  return c;
}

// A 3D texture (lookup_3d.frag: function 8 is textureProj, 10 textureGradOffset) of four 64 x 64 slices with glGenerateMipmap (64 x 64 x 4 down to 1 x 1 x 1),
// stored in `format`, with `wrap` on s, t and r. What it must show follows make_case.
Case three_d_case(const std::string& format, const std::string& min, const std::string& mag, const std::string& wrap, int fn) {
  Case c = make_case("noise_64x64.png", format, min, mag, wrap, fn == 10 ? 3 : fn);
  c.sets = {"fragment=\"sampling/lookup_3d.frag\"",
            "textures.u_tex={\"path\": null, \"target\": \"GL_TEXTURE_3D\", \"layers\": [\"sampling/noise_64x64.png\", "
            "\"sampling/noise_64x64_layer1.png\", \"sampling/noise_64x64_layer2.png\", \"sampling/noise_64x64_layer3.png\"], "
            "\"internalformat\": \"" + format + "\", \"generate_mipmap\": true, \"min_filter\": \"" + min +
                "\", \"mag_filter\": \"" + mag + "\", \"wrap\": \"" + wrap + "\"}",
            function(fn)};
  return c;
}

// A rectangle texture (lookup_rect.frag, coordinates in texels; or lookup_rect_shadow.frag on a
// depth format): one level of `file` in `format`, clamp wraps and mipmap-free filters only. What
// it must show follows make_case (function 1, textureProj, has an implicit LOD as function 0;
// function 8, textureGradOffset, a LOD per lookup as function 3).
Case rect_case(const std::string& file, const std::string& format, const std::string& min, const std::string& mag,
               const std::string& wrap, int fn, bool shadow = false) {
  Case c = make_case(file, format, min, mag, wrap, fn == 1 ? 0 : fn == 8 ? 3 : fn);
  c.sets = {std::string("fragment=\"sampling/lookup_rect") + (shadow ? "_shadow" : "") + ".frag\"",
            "textures.u_tex={\"path\": \"sampling/" + file + "\", \"target\": \"GL_TEXTURE_RECTANGLE\", \"internalformat\": \"" +
                format + "\", \"generate_mipmap\": false, \"min_filter\": \"" + min + "\", \"mag_filter\": \"" + mag +
                "\", \"wrap\": \"" + wrap + "\", \"border_color\": [0.25, 1.5, -1, 0.5]" +
                (shadow ? ", \"compare_mode\": \"compare_ref_to_texture\", \"compare_func\": \"lequal\"" : "") + "}",
            "uniforms={\"u_size_lod\": null}", function(fn)};
  return c;
}

// GL 4.6 table 8.18: every buffer texture format, and the scene buffer its bytes come from
// (sampling_sweep.json's buffers: random bytes, or finite floats and half floats for the float
// formats, whose random bit patterns would include NaNs).
const char* const kBufferFormats[] = {
    "GL_R8",      "GL_R16",     "GL_R16F",    "GL_R32F",     "GL_R8I",      "GL_R16I",     "GL_R32I",
    "GL_R8UI",    "GL_R16UI",   "GL_R32UI",   "GL_RG8",      "GL_RG16",     "GL_RG16F",    "GL_RG32F",
    "GL_RG8I",    "GL_RG16I",   "GL_RG32I",   "GL_RG8UI",    "GL_RG16UI",   "GL_RG32UI",   "GL_RGB32F",
    "GL_RGB32I",  "GL_RGB32UI", "GL_RGBA8",   "GL_RGBA16",   "GL_RGBA16F",  "GL_RGBA32F",  "GL_RGBA8I",
    "GL_RGBA16I", "GL_RGBA32I", "GL_RGBA8UI", "GL_RGBA16UI", "GL_RGBA32UI"};

// texelFetch (function 0) or textureSize (9) on a buffer texture of `format` over the range
// [offset, offset + size) of its buffer: size need not be a whole number of texels (GL takes the
// whole ones). Bit-exact.
Case buffer_case(const std::string& format, std::size_t offset, std::size_t size, int fn) {
  const texture::TexelFormat f = *texture::parse_texel_format(format);
  const texture::TexelFormatInfo& fi = texture::info(f);
  const std::string buffer = fi.type == texture::ChannelType::kFloat32   ? "noise_floats"
                             : fi.type == texture::ChannelType::kFloat16 ? "noise_halfs"
                                                                         : "noise_bytes";
  const std::string shader = fi.signed_integer() ? "_int" : fi.unsigned_integer() ? "_uint" : "";
  const std::size_t texels = size / std::size_t(fi.bytes_per_texel());
  return Case{{"fragment=\"sampling/lookup_buffer" + shader + ".frag\"",
               "textures.u_tex={\"path\": null, \"generate_mipmap\": null, \"min_filter\": null, \"mag_filter\": null, "
               "\"wrap\": null, \"target\": \"GL_TEXTURE_BUFFER\", \"buffer\": \"" + buffer + "\", \"internalformat\": \"" +
                   format + "\", \"offset\": " + std::to_string(offset) + ", \"size\": " + std::to_string(size) + "}",
               "uniforms={\"u_size_lod\": null, \"u_count\": " + std::to_string(texels) + "}", function(fn)}};
}

// A cube map (lookup_cube.frag; lookup_cube_array.frag for a cube map array of two cubes) of 16 x
// 16 faces with glGenerateMipmap, stored in `format`, GL_TEXTURE_CUBE_MAP_SEAMLESS on or off; or a
// samplerCubeShadow (lookup_cube_shadow.frag) on gray faces stored in a depth format, one level.
// The wraps are clamp-to-edge: llvmpipe ignores them on cube maps, where GL applies them to each
// face when seamless filtering is off (docs/textures.md). What it must show follows make_case;
// where seamless GL_LINEAR filtering meets a corner, llvmpipe sums the whole vector's texels by
// weight (texture::cube_corners), as tessref does for the same vectors.
Case cube_case(bool array, const std::string& format, const std::string& min, const std::string& mag, bool seamless, int fn,
               const std::string& compare_func = "") {
  const bool shadow = !compare_func.empty();
  std::string layers;
  for (int k = 0; k < (array ? 12 : 6); ++k)
    layers += std::string(k ? ", " : "") + "\"sampling/cube_16_" + (shadow ? "depth" : "face") + std::to_string(k) + ".png\"";
  Case c;
  if (format.find("SRGB") != std::string::npos) c.tolerance = 0.0089f;  // as make_case says
  c.sets = {std::string("fragment=\"sampling/lookup_cube") + (shadow ? "_shadow" : array ? "_array" : "") + ".frag\"",
            "textures.u_tex={\"path\": null, \"target\": \"" + std::string(array ? "GL_TEXTURE_CUBE_MAP_ARRAY" : "GL_TEXTURE_CUBE_MAP") +
                "\", \"layers\": [" + layers + "], \"internalformat\": \"" + format + "\", \"generate_mipmap\": " +
                (shadow ? "false" : "true") + ", \"min_filter\": \"" + min + "\", \"mag_filter\": \"" + mag +
                "\", \"wrap\": \"clamp_to_edge\"" +
                (shadow ? ", \"compare_mode\": \"compare_ref_to_texture\", \"compare_func\": \"" + compare_func + "\"" : "") + "}",
            function(fn)};
  // textureQueryLod at (x, y, 0): llvmpipe's LOD query passes no r for a cube map (its layer slot),
  // so the two agree but where the quad's x and y do not change: there llvmpipe's ρ comes from an
  // r it was not given. At most this share (measured: 2 of 16,384).
  if (fn == 7) c.max_differing = 0.0005;
  if (seamless) c.sets.push_back("draw.enable=[\"GL_TEXTURE_CUBE_MAP_SEAMLESS\"]");
  return c;
}

// The suite's cases: each lookup function on the fixed-point path (RGBA8, repeat) and on the
// float path (RGBA32F, mirrored repeat); every wrap and filter on both; a size that is not a
// power of two; each format; and the sampler state keys.
std::vector<Case> suite_cases() {
  std::vector<Case> cases;
  for (int f = 0; f < 10; ++f) {
    cases.push_back(make_case("noise_64x64.png", "GL_RGBA8", "linear_mipmap_linear", "linear", "repeat", f));
    cases.push_back(make_case("noise_64x64.exr", "GL_RGBA32F", "linear_mipmap_linear", "linear", "mirrored_repeat", f));
  }
  for (const char* wrap : {"repeat", "mirrored_repeat", "clamp_to_edge", "clamp_to_border", "mirror_clamp_to_edge"})
    for (const char* min : {"nearest_mipmap_nearest", "linear_mipmap_nearest", "nearest_mipmap_linear", "linear"})
      for (const char* mag : {"nearest", "linear"}) {
        cases.push_back(make_case("noise_24x10.png", "GL_RGBA8", min, mag, wrap, 0));
        cases.push_back(make_case("noise_64x64.exr", "GL_RGBA32F", min, mag, wrap, 2));
      }
  for (const char* format : {"GL_RGBA16F", "GL_RGBA8", "GL_SRGB8_ALPHA8"})
    for (int f : {0, 3})
      cases.push_back(make_case(std::string(format) == "GL_RGBA16F" ? "noise_64x64.exr" : "noise_64x64.png", format,
                                "linear_mipmap_linear", "linear", "clamp_to_edge", f));
  // Generated levels of a size that is not a power of two, in float: where llvmpipe's blit samples.
  for (int f : {0, 3}) cases.push_back(make_case("noise_24x10.png", "GL_RGBA32F", "linear_mipmap_linear", "linear", "repeat", f));
  cases.push_back(make_case("noise_64x64_gray.png", "GL_R8", "linear_mipmap_linear", "linear", "repeat", 0));
  cases.push_back(make_case("noise_64x64_rgb.png", "GL_RGB8", "linear_mipmap_nearest", "linear", "repeat", 1));
  // Sampler state: LOD bias (quantized to 1/256 on both) and range, base and max level, a range
  // of one LOD, swizzle and border colour.
  auto state = [](int fn, const std::vector<std::string>& extra) {
    return make_case("noise_64x64.png", "GL_RGBA8", "linear_mipmap_linear", "linear", "clamp_to_border", fn, extra);
  };
  cases.push_back(state(0, {"textures.u_tex.lod_bias=0.3", "textures.u_tex.min_lod=1.25", "textures.u_tex.max_lod=5.6"}));
  cases.push_back(state(7, {"textures.u_tex.lod_bias=-0.7", "textures.u_tex.max_lod=3.5"}));
  cases.push_back(state(2, {"textures.u_tex.base_level=1", "textures.u_tex.max_level=4"}));
  cases.push_back(state(9, {"textures.u_tex.base_level=2", "uniforms.u_size_lod=1"}));
  cases.push_back(state(0, {"textures.u_tex.min_lod=2", "textures.u_tex.max_lod=2"}));
  cases.push_back(state(1, {"textures.u_tex.swizzle=[\"blue\", \"zero\", \"red\", \"one\"]",
                            "textures.u_tex.border_color=[0.25, 1.5, -1, 0.5]"}));
  // A sampler object (glBindSampler) overriding the texture's state, from GL's initial values.
  cases.push_back(make_case("noise_64x64.png", "GL_RGBA8", "nearest", "nearest", "repeat", 1,
                            {"textures.u_tex.sampler={\"min_filter\": \"linear_mipmap_nearest\", \"wrap_s\": "
                             "\"mirrored_repeat\", \"lod_bias\": 0.5}"}));
  // textureGather, with offsets, on both paths, a size that is not a power of two, the border and
  // a swizzle (the component is taken through it).
  for (int f : {10, 11, 12}) {
    cases.push_back(make_case("noise_24x10.png", "GL_RGBA8", "linear_mipmap_linear", "linear", "repeat", f));
    cases.push_back(make_case("noise_64x64.exr", "GL_RGBA32F", "nearest", "nearest", "clamp_to_border", f,
                              {"textures.u_tex.border_color=[0.25, 1.5, -1, 0.5]"}));
  }
  cases.push_back(make_case("noise_64x64.png", "GL_SRGB8_ALPHA8", "linear", "linear", "mirrored_repeat", 10,
                            {"textures.u_tex.swizzle=[\"alpha\", \"zero\", \"one\", \"red\"]"}));
  // 16-bit, signed normalized and packed float formats: their generated levels (llvmpipe's render
  // target conversions), implicit LOD and gradients, and a border colour beyond each range.
  for (const auto& [file, format] : std::vector<std::pair<std::string, std::string>>{
           {"noise_64x64.png", "GL_RGBA16"},        {"noise_64x64_rgb.png", "GL_RGB16"},
           {"noise_64x64_gray.png", "GL_R16"},      {"noise_64x64_signed.exr", "GL_RGBA16_SNORM"},
           {"noise_64x64_signed.exr", "GL_RGBA8_SNORM"}, {"noise_64x64_hdr.exr", "GL_R11F_G11F_B10F"},
           {"noise_64x64_hdr.exr", "GL_RGB9_E5"}}) {
    cases.push_back(make_case(file, format, "linear_mipmap_linear", "linear", "repeat", 0));
    cases.push_back(make_case(file, format, "nearest_mipmap_linear", "linear", "clamp_to_border", 3,
                              {"textures.u_tex.border_color=[-2, 0.5, 70000, 1.5]"}));
  }
  // Depth formats read as (d, 0, 0, 1) by a sampler2D.
  for (const char* format : kDepthFormats)
    cases.push_back(make_case("depth_64x64.exr", format, "linear", "nearest", "clamp_to_border", 2,
                              {"textures.u_tex.generate_mipmap=false", "textures.u_tex.border_color=[0.75, 0, 0, 0]"}));
  // Shadow lookups: each function, each comparison, each depth format, both filters.
  for (int fn = 0; fn <= 9; ++fn) cases.push_back(shadow_case("GL_DEPTH_COMPONENT24", "linear", "linear", "repeat", "lequal", fn));
  for (const char* func : kCompareFuncs) cases.push_back(shadow_case("GL_DEPTH_COMPONENT32F", "linear", "linear", "clamp_to_edge", func, 0));
  for (const char* format : kDepthFormats) {
    cases.push_back(shadow_case(format, "nearest", "linear", "clamp_to_border", "greater", 2,
                                {"textures.u_tex.border_color=[0.5, 0, 0, 0]"}));
    cases.push_back(shadow_case(format, "linear", "nearest", "mirrored_repeat", "equal", 6));
  }
  // Integer formats: each one; every lookup on a signed and an unsigned one; every wrap; a border
  // colour beyond each format's range (clamped to the first channel's range, 32-bit ones not).
  for (const IntegerFormat& f : kIntegerFormats)
    cases.push_back(integer_case(f, "nearest_mipmap_nearest", "nearest", "clamp_to_border", 2,
                                 ", \"border_color\": [" + std::string(std::string(f.name).find("UI") != std::string::npos
                                                                           ? "70000, 3000000000, 5, 1024]"
                                                                           : "-70000, 200, -2147483648, 2147483647]")));
  for (int fn = 0; fn < 13; ++fn) {
    cases.push_back(integer_case(kIntegerFormats[0], "nearest_mipmap_nearest", "nearest", "repeat", fn));
    cases.push_back(integer_case(kIntegerFormats[7], "nearest", "nearest", "mirrored_repeat", fn));
  }
  for (const char* wrap : {"repeat", "mirrored_repeat", "clamp_to_edge", "mirror_clamp_to_edge"})
    cases.push_back(integer_case(kIntegerFormats[15], "nearest_mipmap_nearest", "nearest", wrap, 4));
  // 2D arrays: every lookup on the 8-bit and the float path, every wrap with differing filters.
  for (int fn = 0; fn < 13; ++fn) {
    cases.push_back(array_case("GL_RGBA8", "linear_mipmap_linear", "linear", "repeat", fn));
    cases.push_back(array_case("GL_RGBA32F", "linear_mipmap_linear", "linear", "mirrored_repeat", fn));
  }
  for (const char* wrap : {"repeat", "mirrored_repeat", "clamp_to_edge", "clamp_to_border", "mirror_clamp_to_edge"}) {
    cases.push_back(array_case("GL_RGBA8", "nearest_mipmap_nearest", "linear", wrap, 0));
    cases.push_back(array_case("GL_RGBA16F", "linear_mipmap_nearest", "nearest", wrap, 2));
  }
  for (int fn = 0; fn < 13; ++fn) cases.push_back(integer_array_case("nearest_mipmap_nearest", "clamp_to_border", fn));
  cases.push_back(integer_array_case("nearest", "mirrored_repeat", 0));
  for (int fn : {0, 3, 4, 5, 6, 7, 8, 9})
    cases.push_back(shadow_array_case("GL_DEPTH_COMPONENT24", "linear", "linear", "clamp_to_border", "lequal", fn));
  cases.push_back(shadow_array_case("GL_DEPTH_COMPONENT32F", "nearest", "nearest", "repeat", "greater", 0));
  // 1D textures and 1D arrays: every lookup on the 8-bit and the float path, every wrap with
  // differing filters; 1D shadow lookups; buffer textures of every format.
  for (int fn = 0; fn <= 10; ++fn)
    for (bool array : {false, true}) {
      if (array && fn == 10) continue;  // the array's shader has functions 0 to 9
      cases.push_back(one_d_case(array, "GL_RGBA8", "linear_mipmap_linear", "linear", "repeat", fn));
      cases.push_back(one_d_case(array, "GL_RGBA32F", "linear_mipmap_linear", "linear", "mirrored_repeat", fn));
    }
  // A 1D texture's wrap_t is not its own: the 8-bit path does not depend on it.
  cases.push_back(with_sets(one_d_case(false, "GL_RGBA8", "linear_mipmap_linear", "linear", "repeat", 0),
                            {"textures.u_tex.wrap_t=\"clamp_to_border\""}));
  for (const char* wrap : {"repeat", "mirrored_repeat", "clamp_to_edge", "clamp_to_border", "mirror_clamp_to_edge"}) {
    cases.push_back(one_d_case(false, "GL_RGBA8", "nearest_mipmap_nearest", "linear", wrap, 0));
    cases.push_back(one_d_case(true, "GL_RGBA16F", "linear_mipmap_nearest", "nearest", wrap, 2));
  }
  for (int fn : {0, 1, 2, 3, 4, 5, 6, 9})
    cases.push_back(one_d_shadow_case("GL_DEPTH_COMPONENT32F", "linear", "linear", "clamp_to_border", "lequal", fn));
  cases.push_back(one_d_shadow_case("GL_DEPTH_COMPONENT16", "nearest", "linear", "repeat", "greater", 0));
  for (const char* format : kBufferFormats) cases.push_back(buffer_case(format, 256, 4003, 0));
  // Rectangle textures: every lookup on the 8-bit and the float path, a size that is not a power
  // of two, both wraps and differing filters; shadow lookups.
  for (int fn : {0, 1, 3, 4, 6, 8, 9, 10, 11}) {
    cases.push_back(rect_case("noise_24x10.png", "GL_RGBA8", "linear", "linear", "clamp_to_edge", fn));
    cases.push_back(rect_case("noise_64x64.exr", "GL_RGBA32F", "linear", "linear", "clamp_to_border", fn));
  }
  for (const char* wrap : {"clamp_to_edge", "clamp_to_border"}) {
    cases.push_back(rect_case("noise_24x10.png", "GL_RGBA8", "nearest", "linear", wrap, 0));
    cases.push_back(rect_case("noise_64x64.exr", "GL_RGBA16F", "linear", "nearest", wrap, 3));
  }
  for (int fn : {0, 1, 3, 4, 10}) cases.push_back(rect_case("depth_64x64.exr", "GL_DEPTH_COMPONENT24", "linear", "linear", "clamp_to_border", fn, true));
  // 3D textures: every lookup on the 8-bit and the float path, every wrap with differing filters.
  for (int fn = 0; fn <= 10; ++fn) {
    cases.push_back(three_d_case("GL_RGBA8", "linear_mipmap_linear", "linear", "repeat", fn));
    cases.push_back(three_d_case("GL_RGBA32F", "linear_mipmap_linear", "linear", "mirrored_repeat", fn));
  }
  for (const char* wrap : {"repeat", "mirrored_repeat", "clamp_to_edge", "clamp_to_border", "mirror_clamp_to_edge"}) {
    cases.push_back(three_d_case("GL_RGBA8", "nearest_mipmap_nearest", "linear", wrap, 0));
    cases.push_back(three_d_case("GL_RGBA16F", "linear_mipmap_nearest", "nearest", wrap, 2));
  }
  cases.push_back(buffer_case("GL_RGBA32UI", 0, 65536, 0));
  cases.push_back(buffer_case("GL_RGB32F", 0, 16384, 9));
  // Cube maps and cube map arrays: every lookup on the 8-bit and the float path, seamless or not;
  // differing filters; shadow lookups.
  for (int fn : {0, 1, 2, 3, 4, 5, 7})  // 6, textureQueryLod of a direction with z, differs (docs/textures.md)
    for (bool seamless : {false, true})
      for (bool array : {false, true}) {
        cases.push_back(cube_case(array, "GL_RGBA8", "linear_mipmap_linear", "linear", seamless, fn));
        cases.push_back(cube_case(array, "GL_RGBA32F", "linear_mipmap_linear", "linear", seamless, fn));
      }
  for (bool seamless : {false, true})
    for (const char* min : {"nearest_mipmap_nearest", "linear_mipmap_nearest", "nearest", "linear"})
      for (const char* mag : {"nearest", "linear"}) {
        cases.push_back(cube_case(false, "GL_RGBA8", min, mag, seamless, 0));
        cases.push_back(cube_case(false, "GL_RGBA16F", min, mag, seamless, 2));
      }
  for (int fn : {0, 1, 3, 4, 5})
    for (bool seamless : {false, true})
      cases.push_back(cube_case(false, "GL_DEPTH_COMPONENT24", "linear", "linear", seamless, fn, "lequal"));
  return cases;
}

// Every format x minification filter x magnification filter x wrap x lookup.
std::vector<Case> full_cases() {
  struct Format {
    const char* file;
    const char* name;
  };
  const Format formats[] = {{"noise_64x64.png", "GL_RGBA8"},         {"noise_24x10.png", "GL_RGBA8"},
                            {"noise_64x64.exr", "GL_RGBA32F"},       {"noise_64x64.exr", "GL_RGBA16F"},
                            {"noise_64x64.png", "GL_SRGB8_ALPHA8"},  {"noise_64x64_gray.png", "GL_R8"},
                            {"noise_64x64_rgb.png", "GL_RGB8"},      {"noise_24x10.png", "GL_RGBA32F"},
                            {"noise_64x64.png", "GL_RGBA16"},        {"noise_64x64_signed.exr", "GL_RGBA16_SNORM"},
                            {"noise_64x64_signed.exr", "GL_RGBA8_SNORM"}, {"noise_64x64_hdr.exr", "GL_R11F_G11F_B10F"},
                            {"noise_64x64_hdr.exr", "GL_RGB9_E5"}};
  std::vector<Case> cases;
  for (const Format& f : formats)
    for (const char* min : {"nearest", "linear", "nearest_mipmap_nearest", "linear_mipmap_nearest",
                            "nearest_mipmap_linear", "linear_mipmap_linear"})
      for (const char* mag : {"nearest", "linear"})
        for (const char* wrap : {"repeat", "mirrored_repeat", "clamp_to_edge", "clamp_to_border", "mirror_clamp_to_edge"})
          for (int fn = 0; fn < 13; ++fn) {
            if (fn == 9 && std::string(wrap) != "repeat") continue;  // sizes do not depend on the wrap
            // textureGather reads GL_LINEAR's footprint whatever the filters: two pairs of them.
            if (fn >= 10 && !(std::string(min) == "nearest" && std::string(mag) == "nearest") &&
                !(std::string(min) == "linear_mipmap_linear" && std::string(mag) == "linear"))
              continue;
            cases.push_back(make_case(f.file, f.name, min, mag, wrap, fn));
          }
  for (const char* format : {"GL_RGBA8", "GL_RGBA32F", "GL_SRGB8_ALPHA8"})
    for (const char* min : {"nearest", "linear", "nearest_mipmap_nearest", "linear_mipmap_nearest", "nearest_mipmap_linear",
                            "linear_mipmap_linear"})
      for (const char* mag : {"nearest", "linear"})
        for (const char* wrap : {"repeat", "mirrored_repeat", "clamp_to_edge", "clamp_to_border", "mirror_clamp_to_edge"})
          for (int fn = 0; fn < 13; ++fn)
            if (fn != 9 || std::string(wrap) == "repeat") cases.push_back(array_case(format, min, mag, wrap, fn));
  for (const IntegerFormat& f : kIntegerFormats)
    for (const char* min : {"nearest", "nearest_mipmap_nearest"})
      for (const char* wrap : {"repeat", "mirrored_repeat", "clamp_to_edge", "clamp_to_border", "mirror_clamp_to_edge"})
        for (int fn = 0; fn < 13; ++fn)
          if (fn != 9 || std::string(wrap) == "repeat") cases.push_back(integer_case(f, min, "nearest", wrap, fn));
  for (const char* min : {"nearest", "nearest_mipmap_nearest"})
    for (const char* wrap : {"repeat", "mirrored_repeat", "clamp_to_edge", "clamp_to_border", "mirror_clamp_to_edge"})
      for (int fn = 0; fn < 13; ++fn)
        if (fn != 9 || std::string(wrap) == "repeat") cases.push_back(integer_array_case(min, wrap, fn));
  for (const char* format : kDepthFormats)
    for (const char* wrap : {"repeat", "mirrored_repeat", "clamp_to_edge", "clamp_to_border", "mirror_clamp_to_edge"})
      for (int fn : {0, 3, 4, 5, 6, 7, 8})
        cases.push_back(shadow_array_case(format, "linear", "nearest", wrap, "lequal", fn));
  // 1D textures, 1D arrays (functions 0 to 9) and 3D textures.
  for (const char* format : {"GL_RGBA8", "GL_RGBA32F", "GL_SRGB8_ALPHA8"})
    for (const char* min : {"nearest", "linear", "nearest_mipmap_nearest", "linear_mipmap_nearest", "nearest_mipmap_linear",
                            "linear_mipmap_linear"})
      for (const char* mag : {"nearest", "linear"})
        for (const char* wrap : {"repeat", "mirrored_repeat", "clamp_to_edge", "clamp_to_border", "mirror_clamp_to_edge"})
          for (int fn = 0; fn <= 10; ++fn) {
            if (fn == 9 && std::string(wrap) != "repeat") continue;
            cases.push_back(one_d_case(false, format, min, mag, wrap, fn));
            if (fn < 10) cases.push_back(one_d_case(true, format, min, mag, wrap, fn));
            cases.push_back(three_d_case(format, min, mag, wrap, fn));
          }
  for (const auto& [file, format] : std::vector<std::pair<std::string, std::string>>{
           {"noise_24x10.png", "GL_RGBA8"}, {"noise_64x64.png", "GL_RGBA8"}, {"noise_64x64.exr", "GL_RGBA32F"},
           {"noise_24x10.png", "GL_RGBA32F"}, {"noise_64x64.png", "GL_SRGB8_ALPHA8"}})
    for (const char* min : {"nearest", "linear"})
      for (const char* mag : {"nearest", "linear"})
        for (const char* wrap : {"clamp_to_edge", "clamp_to_border"})
          for (int fn : {0, 1, 3, 4, 6, 8, 9, 10, 11}) cases.push_back(rect_case(file, format, min, mag, wrap, fn));
  for (const char* format : kDepthFormats)
    for (const char* min : {"nearest", "linear"})
      for (const char* wrap : {"clamp_to_edge", "clamp_to_border"})
        for (int fn : {0, 1, 3, 4, 10}) cases.push_back(rect_case("depth_64x64.exr", format, min, "linear", wrap, fn, true));
  for (const char* format : {"GL_DEPTH_COMPONENT16", "GL_DEPTH_COMPONENT32F"})
    for (const char* wrap : {"repeat", "mirrored_repeat", "clamp_to_edge", "clamp_to_border", "mirror_clamp_to_edge"})
      for (int fn = 0; fn <= 6; ++fn)
        for (const char* func : {"lequal", "notequal"}) cases.push_back(one_d_shadow_case(format, "linear", "nearest", wrap, func, fn));
  for (const char* format : kBufferFormats)
    for (std::size_t offset : {0, 256, 4096})
      for (std::size_t size : {1, 15, 4003, 12288}) {
        // textureSize of a range too short for one texel is 0 in GL and 1 on llvmpipe
        // (docs/textures.md): those ranges' cases fetch.
        const bool empty = size < std::size_t(texture::info(*texture::parse_texel_format(format)).bytes_per_texel());
        cases.push_back(buffer_case(format, offset, size, offset == 0 && !empty ? 9 : 0));
      }
  // Cube maps and cube map arrays: every format class x filter pair x seamless x lookup; shadow
  // cube maps in each depth format.
  for (const char* format : {"GL_RGBA8", "GL_RGBA32F", "GL_SRGB8_ALPHA8"})
    for (const char* min : {"nearest", "linear", "nearest_mipmap_nearest", "linear_mipmap_nearest", "nearest_mipmap_linear",
                            "linear_mipmap_linear"})
      for (const char* mag : {"nearest", "linear"})
        for (bool seamless : {false, true})
          for (int fn : {0, 1, 2, 3, 4, 5, 7}) {
            if (fn == 5 && seamless) continue;  // sizes do not depend on it
            // textureQueryLod where the filters need no LOD (no mip filter, equal filters): llvmpipe
            // takes it from the quad's differences of face coordinates (docs/textures.md).
            if (fn == 7 && std::string(min).find("mipmap") == std::string::npos && linear_image(min) == linear_image(mag))
              continue;
            cases.push_back(cube_case(false, format, min, mag, seamless, fn));
            if (fn != 5) cases.push_back(cube_case(true, format, min, mag, seamless, fn));
          }
  for (const char* format : kDepthFormats)
    for (const char* min : {"nearest", "linear"})
      for (bool seamless : {false, true})
        for (int fn : {0, 1, 3, 4})
          for (const char* func : {"lequal", "notequal"}) cases.push_back(cube_case(false, format, min, "linear", seamless, fn, func));
  for (const char* format : kDepthFormats)
    for (const char* min : {"nearest", "linear"})
      for (const char* mag : {"nearest", "linear"})
        for (const char* wrap : {"repeat", "mirrored_repeat", "clamp_to_edge", "clamp_to_border", "mirror_clamp_to_edge"}) {
          for (int fn = 0; fn <= 8; ++fn) cases.push_back(shadow_case(format, min, mag, wrap, "lequal", fn));
          for (const char* func : kCompareFuncs) cases.push_back(shadow_case(format, min, mag, wrap, func, 6));
        }
  return cases;
}

TEST(SamplingSweepVsLlvmpipe, EveryLookupMatchesBitForBit) {
  TESSREF_REQUIRE_GL(ctx);
  const char* mode = std::getenv("TESSREF_SAMPLING_SWEEP");
  const bool full = mode && std::string(mode) == "full";
  std::vector<Case> cases = full ? full_cases() : suite_cases();
  // TESSREF_SAMPLING_SWEEP_MATCH=TEXT keeps the cases whose keys contain TEXT (a lookup shader's
  // name, a format): a part of the sweep, run on its own.
  if (const char* match = std::getenv("TESSREF_SAMPLING_SWEEP_MATCH"))
    std::erase_if(cases, [&](const Case& c) { return joined(c.sets).find(match) == std::string::npos; });
  std::size_t lookups = 0, identical = 0, cases_exact = 0;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const Case& c = cases[k];
    const Outcome o = compare(*ctx, c.sets, c.tolerance);
    lookups += o.lookups;
    identical += o.identical;
    cases_exact += o.identical == o.lookups;
    if (o.identical != o.lookups)
      std::printf("[ figures  ] %s: %zu of %zu identical, largest difference %g; first: %s\n", joined(c.sets).c_str(),
                  o.identical, o.lookups, double(o.max_difference), o.first.c_str());
    // Every lookup within the tolerance (0: identical), but for the stated share.
    EXPECT_LE(double(o.beyond), c.max_differing * double(o.lookups)) << joined(c.sets) << "\n" << o.first;
    if (full && (k + 1) % 100 == 0) std::printf("[ progress ] %zu of %zu cases\n", k + 1, cases.size());
  }
  std::printf("[ figures  ] sampling sweep (%s): %zu cases, %zu lookups, %zu identical (%zu cases bit-exact)\n",
              full ? "full" : "suite", cases.size(), lookups, identical, cases_exact);
  if (!std::getenv("TESSREF_SAMPLING_SWEEP_MATCH")) {
    EXPECT_GE(lookups, 20000u);
  }
}

}  // namespace
}  // namespace tessref::glref
