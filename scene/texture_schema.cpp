#include "scene/texture_schema.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace tessref {
namespace {

using texture::Filter;
using texture::Swizzle;
using texture::Wrap;

constexpr std::array<std::pair<const char*, Filter>, 6> kFilters{{
    {"nearest", Filter::Nearest},
    {"linear", Filter::Linear},
    {"nearest_mipmap_nearest", Filter::NearestMipmapNearest},
    {"linear_mipmap_nearest", Filter::LinearMipmapNearest},
    {"nearest_mipmap_linear", Filter::NearestMipmapLinear},
    {"linear_mipmap_linear", Filter::LinearMipmapLinear},
}};
constexpr std::array<std::pair<const char*, Wrap>, 5> kWraps{{
    {"repeat", Wrap::Repeat},
    {"mirrored_repeat", Wrap::MirroredRepeat},
    {"clamp_to_edge", Wrap::ClampToEdge},
    {"clamp_to_border", Wrap::ClampToBorder},
    {"mirror_clamp_to_edge", Wrap::MirrorClampToEdge},
}};
constexpr std::array<std::pair<const char*, bool>, 2> kCompareModes{{
    {"none", false}, {"compare_ref_to_texture", true},
}};
constexpr std::array<std::pair<const char*, texture::CompareFunc>, 8> kCompareFuncs{{
    {"never", texture::CompareFunc::Never}, {"less", texture::CompareFunc::Less},
    {"equal", texture::CompareFunc::Equal}, {"lequal", texture::CompareFunc::Lequal},
    {"greater", texture::CompareFunc::Greater}, {"notequal", texture::CompareFunc::Notequal},
    {"gequal", texture::CompareFunc::Gequal}, {"always", texture::CompareFunc::Always},
}};
constexpr std::array<std::pair<const char*, Swizzle>, 6> kSwizzles{{
    {"red", Swizzle::Red}, {"green", Swizzle::Green}, {"blue", Swizzle::Blue},
    {"alpha", Swizzle::Alpha}, {"zero", Swizzle::Zero}, {"one", Swizzle::One},
}};

template <class Enum, std::size_t N>
std::string names(const std::array<std::pair<const char*, Enum>, N>& table, std::size_t count = N) {
  std::string out;
  for (std::size_t i = 0; i < count; ++i) out += (i ? ", " : "") + std::string(table[i].first);
  return out;
}

// A string key that names one of the first `count` entries of table.
template <class Enum, std::size_t N>
Enum choice(JsonObject& o, const std::string& key, const std::array<std::pair<const char*, Enum>, N>& table,
            std::size_t count = N) {
  const std::string s = o.string(key);
  o.describe(key, "one of " + names(table, count));
  for (std::size_t i = 0; i < count; ++i)
    if (s == table[i].first) return table[i].second;
  o.fail(key, "expected one of " + names(table, count) + ", got \"" + s + "\"");
}

constexpr std::array<std::pair<const char*, texture::Target>, 9> kTargets{{
    {"GL_TEXTURE_1D", texture::Target::k1D},
    {"GL_TEXTURE_2D", texture::Target::k2D},
    {"GL_TEXTURE_3D", texture::Target::k3D},
    {"GL_TEXTURE_RECTANGLE", texture::Target::kRectangle},
    {"GL_TEXTURE_1D_ARRAY", texture::Target::k1DArray},
    {"GL_TEXTURE_2D_ARRAY", texture::Target::k2DArray},
    {"GL_TEXTURE_BUFFER", texture::Target::kBuffer},
    {"GL_TEXTURE_CUBE_MAP", texture::Target::kCube},
    {"GL_TEXTURE_CUBE_MAP_ARRAY", texture::Target::kCubeArray},
}};

void read_internalformat(JsonObject& o, TextureSetting& t) {
  if (!o.has("internalformat")) return;
  const std::string f = o.string("internalformat");
  o.describe("internalformat", "one of " + texture::texel_format_names());
  t.format = texture::parse_texel_format(f);
  if (!t.format) o.fail("internalformat", "expected one of " + texture::texel_format_names() + ", got \"" + f + "\"");
}

// GL 4.6 table 8.18: the formats a buffer texture may have.
bool buffer_texture_format(texture::TexelFormat f) {
  using TF = texture::TexelFormat;
  switch (f) {
    case TF::kR8: case TF::kR16: case TF::kR16F: case TF::kR32F: case TF::kR8I: case TF::kR16I: case TF::kR32I:
    case TF::kR8Ui: case TF::kR16Ui: case TF::kR32Ui:
    case TF::kRg8: case TF::kRg16: case TF::kRg16F: case TF::kRg32F: case TF::kRg8I: case TF::kRg16I: case TF::kRg32I:
    case TF::kRg8Ui: case TF::kRg16Ui: case TF::kRg32Ui:
    case TF::kRgb32F: case TF::kRgb32I: case TF::kRgb32Ui:
    case TF::kRgba8: case TF::kRgba16: case TF::kRgba16F: case TF::kRgba32F: case TF::kRgba8I: case TF::kRgba16I:
    case TF::kRgba32I: case TF::kRgba8Ui: case TF::kRgba16Ui: case TF::kRgba32Ui:
      return true;
    default: return false;
  }
}
std::string buffer_texture_formats() {
  std::string out;
  for (int k = 0; k <= int(texture::TexelFormat::kRgb32F); ++k)
    if (buffer_texture_format(texture::TexelFormat(k)))
      out += (out.empty() ? "" : ", ") + std::string(texture::info(texture::TexelFormat(k)).gl_name);
  return out;
}

// The keys read_sampler_state reads (glTexParameter's and glSamplerParameter's state).
constexpr std::array<const char*, 14> kSamplerStateKeys{
    "filter", "min_filter", "mag_filter", "wrap", "wrap_s", "wrap_t", "wrap_r", "border_color", "min_lod", "max_lod",
    "lod_bias", "compare_mode", "compare_func", "max_anisotropy"};

// GL_TEXTURE_BUFFER: a range of one of the scene's buffers, read as texels of a format of table
// 8.18 (glTexBufferRange). It has no images, levels or sampler state.
void read_buffer_texture(JsonObject& o, TextureSetting& t) {
  std::vector<const char*> keys{"path", "levels", "layers", "raw_size", "generate_mipmap", "sampler", "base_level", "max_level",
                                 "swizzle"};
  keys.insert(keys.end(), kSamplerStateKeys.begin(), kSamplerStateKeys.end());
  for (const char* key : keys)
    if (o.has(key))
      o.fail(key, "a GL_TEXTURE_BUFFER texture has no images, levels or sampler state (GL 4.6 8.9): its texels are "
                  "the bytes of `buffer` from `offset`, read by texelFetch");
  o.describe("buffer", "the scene buffer (buffers.NAME) whose bytes the buffer texture reads");
  t.buffer = o.string("buffer");
  if (!o.has("internalformat"))
    o.fail("internalformat", "a GL_TEXTURE_BUFFER needs the format its bytes hold: one of " + buffer_texture_formats());
  read_internalformat(o, t);
  if (!buffer_texture_format(*t.format))
    o.fail("internalformat", std::string(texture::info(*t.format).gl_name) + " is not a buffer texture format (GL 4.6 "
                             "table 8.18): expected one of " + buffer_texture_formats());
  // GL_TEXTURE_BUFFER_OFFSET_ALIGNMENT may be as large as 256 (GL 4.6 table 23.64): a program
  // that relies on less fails on some driver, so tessref asks for 256.
  constexpr std::int64_t kMaxBytes = std::int64_t(1) << 40;
  if (o.has("offset")) {
    o.describe("offset", "a byte offset into the buffer, a multiple of 256 (default 0)");
    t.buffer_offset = std::size_t(o.integer64("offset", 0, kMaxBytes));
    if (t.buffer_offset % 256)
      o.fail("offset", std::to_string(t.buffer_offset) + " is not a multiple of 256: GL_TEXTURE_BUFFER_OFFSET_ALIGNMENT "
                       "may be as large as 256, and glTexBufferRange refuses an offset that is not a multiple of it");
  }
  if (o.has("size")) {
    o.describe("size", "bytes of the range, > 0 (default: the rest of the buffer)");
    t.buffer_size = std::size_t(o.integer64("size", 1, kMaxBytes));
  }
  o.finish();
}

// The sampler state keys of a texture, or of a sampler object (glSamplerParameter).
void read_sampler_state(JsonObject& o, texture::SamplerState& s, const texture::TexelFormatInfo& format) {
  // filter and wrap set both filters and both wraps; the specific keys override them.
  if (o.has("filter")) s.min_filter = s.mag_filter = choice(o, "filter", kFilters, 2);
  if (o.has("min_filter")) s.min_filter = choice(o, "min_filter", kFilters);
  if (o.has("mag_filter")) s.mag_filter = choice(o, "mag_filter", kFilters, 2);
  if (o.has("wrap")) s.wrap_s = s.wrap_t = s.wrap_r = choice(o, "wrap", kWraps);
  if (o.has("wrap_s")) s.wrap_s = choice(o, "wrap_s", kWraps);
  if (o.has("wrap_t")) s.wrap_t = choice(o, "wrap_t", kWraps);
  if (o.has("wrap_r")) s.wrap_r = choice(o, "wrap_r", kWraps);
  if (o.has("border_color") && format.integer()) {
    // glTexParameterIiv (signed formats) or glTexParameterIuiv (unsigned ones).
    const bool is_signed = format.signed_integer();
    const std::int64_t lo = is_signed ? INT32_MIN : 0, hi = is_signed ? INT32_MAX : UINT32_MAX;
    const std::string range = std::to_string(lo) + " to " + std::to_string(hi);
    o.describe("border_color", std::string("[r, g, b, a] whole numbers from ") + range + " for an integer format");
    const nlohmann::json& b = o.value("border_color");
    if (!b.is_array() || b.size() != 4)
      o.fail("border_color", std::string(format.gl_name) + " is an integer format: expected [r, g, b, a], whole numbers from " +
                                 range + " (glTexParameterI" + (is_signed ? "iv" : "uiv") + "), got " + describe_json(b));
    for (std::size_t c = 0; c < 4; ++c) {
      const bool whole = b[c].is_number_integer() || (b[c].is_number_float() && b[c].get<double>() == std::floor(b[c].get<double>()));
      const double v = b[c].is_number() ? b[c].get<double>() : 0.0;
      if (!whole || v < double(lo) || v > double(hi))
        o.fail("border_color." + std::to_string(c), std::string(format.gl_name) + " is an integer format: expected a whole number from " +
                                                        range + ", got " + describe_json(b[c]));
      s.border_integer[c] = std::int64_t(v);
    }
  } else if (o.has("border_color")) {
    const glm::vec4 b = o.rgba("border_color");
    s.border = {b.r, b.g, b.b, b.a};
  }
  if (o.has("min_lod")) s.min_lod = o.number("min_lod");
  if (o.has("max_lod")) s.max_lod = o.number("max_lod");
  if (o.has("lod_bias")) s.lod_bias = o.number("lod_bias");
  if (o.has("compare_mode")) s.compare = choice(o, "compare_mode", kCompareModes);
  if (o.has("compare_func")) s.compare_func = choice(o, "compare_func", kCompareFuncs);
  if (o.has("max_anisotropy")) {
    // GL_TEXTURE_MAX_ANISOTROPY (GL 4.6 8.14.5): 1 (GL's initial value) filters isotropically.
    // llvmpipe filters anisotropically above 1 (Mesa's lp_bld_sample aniso path, up to 16), which
    // tessref does not yet reproduce: refused rather than drawn isotropically.
    o.describe("max_anisotropy", "GL_TEXTURE_MAX_ANISOTROPY: 1 (isotropic filtering, GL's default)");
    const double a = o.number("max_anisotropy");
    if (!(a >= 1.0)) o.fail("max_anisotropy", "GL_TEXTURE_MAX_ANISOTROPY below 1 is GL_INVALID_VALUE (GL 4.6 8.14.5)");
    if (a > 1.0)
      o.fail("max_anisotropy", "tessref does not filter anisotropically (GL_TEXTURE_MAX_ANISOTROPY " + o.value("max_anisotropy").dump() +
                                   "); llvmpipe does, so an image drawn isotropically would differ from a driver's: give 1");
  }
}

// GL_TEXTURE_RECTANGLE (GL 4.6 8.10, 8.14): one level, texel coordinates, and glTexParameter
// refuses mipmap filters, the repeating and mirrored wraps and a base or max level other than 0.
void check_rectangle(JsonObject& o, TextureSetting& t) {
  const std::string one_level = "a GL_TEXTURE_RECTANGLE has level 0 alone";
  if (t.levels.size() > 1) o.fail("levels", one_level + ": give path");
  if (t.generate_mipmaps) o.fail("generate_mipmap", one_level + " (glGenerateMipmap refuses it: GL_INVALID_ENUM)");
  if (t.base_level != 0) o.fail("base_level", one_level + " (GL_TEXTURE_BASE_LEVEL other than 0: GL_INVALID_OPERATION)");
  if (o.has("max_level") && t.max_level != 0)
    o.fail("max_level", one_level + " (GL_TEXTURE_MAX_LEVEL above 0: GL_INVALID_VALUE)");
  t.max_level = 0;
  if (texture::uses_mipmaps(t.sampler_state.min_filter))
    o.fail("min_filter", std::string("a GL_TEXTURE_RECTANGLE is sampled with nearest or linear only, not ") +
                             texture::gl_name(t.sampler_state.min_filter) + " (glTexParameter: GL_INVALID_ENUM)");
  auto clamps = [](const texture::SamplerState& s) {
    for (Wrap w : {s.wrap_s, s.wrap_t, s.wrap_r})
      if (w != Wrap::ClampToEdge && w != Wrap::ClampToBorder) return false;
    return true;
  };
  if (!clamps(t.sampler_state))
    o.fail(o.has("wrap_s") ? "wrap_s" : o.has("wrap_t") ? "wrap_t" : o.has("wrap_r") ? "wrap_r" : "wrap",
           "a GL_TEXTURE_RECTANGLE wraps with clamp_to_edge (its default) or clamp_to_border only (glTexParameter "
           "refuses the others: GL_INVALID_ENUM)");
  // A sampler object may hold any state; on a rectangle texture tessref takes what glTexParameter would.
  if (t.sampler_object && (!clamps(*t.sampler_object) || texture::uses_mipmaps(t.sampler_object->min_filter)))
    o.fail("sampler", "on a GL_TEXTURE_RECTANGLE, tessref takes a sampler object with nearest or linear minification and "
                      "clamp_to_edge or clamp_to_border wraps (a sampler object starts with GL_NEAREST_MIPMAP_LINEAR and "
                      "GL_REPEAT: give min_filter and wrap)");
}

}  // namespace

TextureSetting read_texture_setting(const std::string& name, const nlohmann::json& value, const std::string& path,
                                    const JsonSource& source, const std::filesystem::path& base_dir) {
  TextureSetting t;
  t.sampler = name;
  auto resolve = [&](const std::string& file) {
    const std::filesystem::path p(file);
    return p.is_relative() ? base_dir / p : p;
  };
  if (value.is_string()) {
    t.levels.push_back(resolve(value.get<std::string>()));
    return t;
  }
  JsonObject o(value, path, source);
  if (o.has("target")) {
    o.describe("target", "one of " + names(kTargets) + " (default GL_TEXTURE_2D)");
    t.target = choice(o, "target", kTargets);
  }
  if (t.target == texture::Target::kBuffer) {
    read_buffer_texture(o, t);
    return t;
  }
  // Targets whose level 0 is several images: a 2D array's layers, a 3D texture's slices, a cube
  // map's faces.
  const bool cube = texture::is_cube(t.target), cube_array = t.target == texture::Target::kCubeArray;
  const bool stacked = t.target == texture::Target::k2DArray || t.target == texture::Target::k3D || cube;
  const bool three_d = t.target == texture::Target::k3D;
  const bool array = texture::is_array(t.target), one_d = texture::dimensions(t.target) == 1;
  const bool has_path = o.has("path"), has_levels = o.has("levels"), has_layers = o.has("layers");
  o.describe("path", "an image file: level 0");
  o.describe("levels", "an array of image files: levels 0, 1, ... (glTexSubImage* per level)");
  o.describe("layers", "a GL_TEXTURE_2D_ARRAY's (or GL_TEXTURE_3D's) level 0: an array of image files, one per layer "
                       "(depth slice); a GL_TEXTURE_CUBE_MAP's six faces, +X, -X, +Y, -Y, +Z, -Z (a "
                       "GL_TEXTURE_CUBE_MAP_ARRAY's: six per cube)");
  if (has_layers && !stacked)
    o.fail("layers", std::string("layers are a 2D array texture's (a 3D texture's slices, a cube map's faces): give "
                                 "\"target\": \"GL_TEXTURE_2D_ARRAY\", \"GL_TEXTURE_3D\" or \"GL_TEXTURE_CUBE_MAP\"") +
                         (t.target == texture::Target::k1DArray ? " (a 1D array's layers are the rows of its path or levels images)" : ""));
  if (int(has_path) + int(has_levels) + int(has_layers) != 1)
    o.fail(has_path ? "levels" : "path", stacked ? std::string("give one of layers (level 0's ") + (three_d ? "slices" : "layers") +
                                                       ", image files), or path or levels (raw bytes of every " +
                                                       (three_d ? "slice" : "layer") + ", with raw_size)"
                                                 : "give either path (level 0) or levels (one file per level)");
  // An array of 1 to `most` image file names (`limit` names the GL limit, if any).
  auto files = [&](const std::string& key, std::size_t most, const std::string& limit) {
    const nlohmann::json& list = o.value(key);
    if (!list.is_array() || list.empty() || list.size() > most)
      o.fail(key, "expected an array of 1 to " + std::to_string(most) + " image files" + limit + ", got " + describe_json(list));
    std::vector<std::filesystem::path> out;
    for (std::size_t k = 0; k < list.size(); ++k) {
      if (!list[k].is_string()) o.fail(key + "." + std::to_string(k), "expected an image file name, got " + describe_json(list[k]));
      out.push_back(resolve(list[k].get<std::string>()));
    }
    return out;
  };
  if (has_layers) {
    t.layers = files("layers", std::size_t(texture::kMaxArrayLayers), " (GL_MAX_ARRAY_TEXTURE_LAYERS)");
    // A cube map's faces in GL's order (GL 4.6 table 8.20's layer numbers); a cube map array's, six
    // per cube (glTexStorage3D refuses a depth that is not a multiple of 6: GL_INVALID_VALUE).
    if (cube && (cube_array ? t.layers.size() % 6 != 0 : t.layers.size() != 6))
      o.fail("layers", std::string(cube_array ? "a GL_TEXTURE_CUBE_MAP_ARRAY's layers come six per cube" : "a GL_TEXTURE_CUBE_MAP has six faces") +
                           " (+X, -X, +Y, -Y, +Z, -Z), and this gives " + std::to_string(t.layers.size()) + " image files");
  }
  else if (has_path) t.levels.push_back(resolve(o.string("path")));
  else t.levels = files("levels", 16, "");
  read_internalformat(o, t);
  if (o.has("raw_size")) {
    // [width], [width, layers], [width, height] or [width, height, layers], with each one's limit.
    std::vector<std::pair<std::string, int>> sides{{"width", texture::kMaxTextureSize}};
    if (!one_d) sides.emplace_back("height", texture::kMaxTextureSize);
    if (array) sides.emplace_back("layers", texture::kMaxArrayLayers);
    if (three_d) sides.emplace_back("depth", texture::kMax3DTextureSize);
    std::string shape;
    for (const auto& [side, most] : sides) shape += (shape.empty() ? "[" : ", ") + side;
    shape += "]";
    const std::string limits =
        three_d ? "whole numbers from 1 to " + std::to_string(texture::kMax3DTextureSize) + " (GL_MAX_3D_TEXTURE_SIZE)"
                : "whole numbers from 1 to " + std::to_string(texture::kMaxTextureSize) + " (GL_MAX_TEXTURE_SIZE)" +
                      (array ? " and layers from 1 to " + std::to_string(texture::kMaxArrayLayers) + " (GL_MAX_ARRAY_TEXTURE_LAYERS)" : "");
    o.describe("raw_size", shape + ": the files are raw texel bytes of internalformat" +
                               (cube ? ", every face of a level" : array ? ", every layer of a level" : three_d ? ", every slice of a level" : "") +
                               ", level 0 this size");
    const nlohmann::json& size = o.value("raw_size");
    if (has_layers) o.fail("raw_size", "raw bytes come in path or levels (every layer of a level in one file), not layers");
    bool ok = size.is_array() && size.size() == sides.size();
    for (std::size_t k = 0; ok && k < sides.size(); ++k)
      ok = size[k].is_number_integer() && size[k].get<long long>() >= 1 &&
           size[k].get<long long>() <= (three_d ? texture::kMax3DTextureSize : sides[k].second);
    if (!ok) o.fail("raw_size", "expected " + shape + ", " + limits + ", got " + describe_json(size));
    if (!t.format) o.fail("raw_size", "raw texel bytes need the internalformat that lays them out");
    t.raw_size = std::array<int, 3>{size[0].get<int>(), one_d ? 1 : size[1].get<int>(),
                                    array || three_d ? size[sides.size() - 1].get<int>() : cube ? 6 : 1};
    const auto [width, height, layers] = *t.raw_size;
    if (cube && width != height)
      o.fail("raw_size", "a cube map's faces are square (glTexStorage refuses a width that is not the height: "
                         "GL_INVALID_VALUE), got " + std::to_string(width) + "x" + std::to_string(height));
    if (cube_array && layers % 6 != 0)
      o.fail("raw_size", "a GL_TEXTURE_CUBE_MAP_ARRAY's layers come six per cube (glTexStorage3D: GL_INVALID_VALUE), got " +
                             std::to_string(layers));
  }
  if (t.target == texture::Target::k2DArray && !has_layers && !t.raw_size)
    o.fail(has_path ? "path" : "levels", "a GL_TEXTURE_2D_ARRAY's image files are its layers: give layers (level 0's), "
                                         "or raw bytes of every layer with raw_size [width, height, layers]");
  if (cube && !has_layers && !t.raw_size)
    o.fail(has_path ? "path" : "levels", std::string("a ") + texture::gl_name(t.target) + "'s image files are its faces: give layers "
                                         "(level 0's faces, +X, -X, +Y, -Y, +Z, -Z" + (cube_array ? ", six per cube" : "") +
                                         "), or raw bytes of every face with raw_size");
  if (three_d && !has_layers && !t.raw_size)
    o.fail(has_path ? "path" : "levels", "a GL_TEXTURE_3D's image files are its depth slices: give layers (level 0's "
                                         "slices), or raw bytes of every slice with raw_size [width, height, depth]");
  if (o.has("generate_mipmap")) {
    t.generate_mipmaps = o.boolean("generate_mipmap");
    if (t.generate_mipmaps && t.levels.size() > 1)
      o.fail("generate_mipmap", "glGenerateMipmap computes levels 1 and up from level 0: give levels or generate_mipmap, not both");
    // GL 4.6 8.14.4: INVALID_OPERATION unless the format is color-renderable and filterable.
    if (t.generate_mipmaps && t.format && texture::info(*t.format).depth)
      o.fail("generate_mipmap", std::string("glGenerateMipmap refuses a depth format (") + texture::info(*t.format).gl_name +
                                    " is not color-renderable, GL 4.6 8.14.4): give its levels");
    if (t.generate_mipmaps && t.format && texture::info(*t.format).integer())
      o.fail("generate_mipmap", std::string("glGenerateMipmap refuses an integer format (") + texture::info(*t.format).gl_name +
                                    " is not filterable, GL 4.6 8.14.4): give its levels");
  }
  const texture::TexelFormatInfo& format = texture::info(t.format.value_or(texture::TexelFormat::kRgba32F));
  const bool rectangle = t.target == texture::Target::kRectangle;
  if (rectangle) t.sampler_state.wrap_s = t.sampler_state.wrap_t = t.sampler_state.wrap_r = Wrap::ClampToEdge;  // GL's initial
  read_sampler_state(o, t.sampler_state, format);
  if (o.has("sampler")) {
    // glBindSampler: a sampler object's state replaces the texture's, from GL's initial values.
    o.describe("sampler", "a sampler object bound to the texture's unit (glBindSampler): its own filter, wrap, "
                          "border_color, LOD and compare keys, from GL's initial values, override the texture's");
    JsonObject so(o.value("sampler"), path + ".sampler", source);
    texture::SamplerState state;  // GL's initial sampler object state
    read_sampler_state(so, state, format);
    so.finish();
    t.sampler_object = state;
  }
  if (o.has("base_level")) t.base_level = o.integer("base_level", 0, 1000);
  if (o.has("max_level")) t.max_level = o.integer("max_level", 0, 1000);
  if (rectangle) check_rectangle(o, t);
  if (o.has("swizzle")) {
    const nlohmann::json& sw = o.value("swizzle");
    o.describe("swizzle", "an array of 4 of " + names(kSwizzles) + " (GL_TEXTURE_SWIZZLE_RGBA)");
    if (!sw.is_array() || sw.size() != 4) o.fail("swizzle", "expected an array of 4 of " + names(kSwizzles) + ", got " + describe_json(sw));
    for (std::size_t c = 0; c < 4; ++c) {
      bool found = false;
      for (const auto& [n, v] : kSwizzles)
        if (sw[c].is_string() && sw[c].get<std::string>() == n) t.swizzle[c] = v, found = true;
      if (!found) o.fail("swizzle." + std::to_string(c), "expected one of " + names(kSwizzles) + ", got " + describe_json(sw[c]));
    }
  }
  const bool compare = t.sampler_object ? t.sampler_object->compare : t.sampler_state.compare;
  if (compare && o.has("swizzle"))
    o.fail("swizzle", "tessref does not swizzle a depth comparison's result (GL_TEXTURE_COMPARE_MODE is "
                      "GL_COMPARE_REF_TO_TEXTURE): leave the swizzle out");
  o.finish();
  return t;
}

}  // namespace tessref
