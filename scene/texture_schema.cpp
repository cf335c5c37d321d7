#include "scene/texture_schema.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <utility>

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

// The sampler state keys of a texture, or of a sampler object (glSamplerParameter).
void read_sampler_state(JsonObject& o, texture::SamplerState& s, const texture::TexelFormatInfo& format) {
  // filter and wrap set both filters and both wraps; the specific keys override them.
  if (o.has("filter")) s.min_filter = s.mag_filter = choice(o, "filter", kFilters, 2);
  if (o.has("min_filter")) s.min_filter = choice(o, "min_filter", kFilters);
  if (o.has("mag_filter")) s.mag_filter = choice(o, "mag_filter", kFilters, 2);
  if (o.has("wrap")) s.wrap_s = s.wrap_t = choice(o, "wrap", kWraps);
  if (o.has("wrap_s")) s.wrap_s = choice(o, "wrap_s", kWraps);
  if (o.has("wrap_t")) s.wrap_t = choice(o, "wrap_t", kWraps);
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
    o.describe("target", "GL_TEXTURE_2D (default) or GL_TEXTURE_2D_ARRAY");
    const std::string target = o.string("target");
    if (target != "GL_TEXTURE_2D" && target != "GL_TEXTURE_2D_ARRAY")
      o.fail("target", "expected GL_TEXTURE_2D or GL_TEXTURE_2D_ARRAY (tessref's targets), got \"" + target + "\"");
    t.array = target == "GL_TEXTURE_2D_ARRAY";
  }
  const bool has_path = o.has("path"), has_levels = o.has("levels"), has_layers = o.has("layers");
  o.describe("path", "an image file: level 0");
  o.describe("levels", "an array of image files: levels 0, 1, ... (glTexSubImage2D per level)");
  o.describe("layers", "a GL_TEXTURE_2D_ARRAY's level 0: an array of image files, one per layer");
  if (has_layers && !t.array)
    o.fail("layers", "layers are a 2D array texture's: give \"target\": \"GL_TEXTURE_2D_ARRAY\"");
  if (int(has_path) + int(has_levels) + int(has_layers) != 1)
    o.fail(has_path ? "levels" : "path", t.array ? "give one of layers (level 0's layers, image files), or path or levels "
                                                   "(raw bytes of every layer, with raw_size)"
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
  if (has_layers) t.layers = files("layers", std::size_t(texture::kMaxArrayLayers), " (GL_MAX_ARRAY_TEXTURE_LAYERS)");
  else if (has_path) t.levels.push_back(resolve(o.string("path")));
  else t.levels = files("levels", 16, "");
  if (o.has("internalformat")) {
    const std::string f = o.string("internalformat");
    o.describe("internalformat", "one of " + texture::texel_format_names());
    t.format = texture::parse_texel_format(f);
    if (!t.format) o.fail("internalformat", "expected one of " + texture::texel_format_names() + ", got \"" + f + "\"");
  }
  if (o.has("raw_size")) {
    o.describe("raw_size", t.array ? "[width, height, layers]: the files are raw texel bytes of internalformat, every "
                                     "layer of a level, level 0 this size"
                                   : "[width, height]: the files are raw texel bytes of internalformat, level 0 this size");
    const nlohmann::json& size = o.value("raw_size");
    auto within = [](const nlohmann::json& v, int most) {
      return v.is_number_integer() && v.get<long long>() >= 1 && v.get<long long>() <= most;
    };
    const std::string sides = "whole numbers from 1 to " + std::to_string(texture::kMaxTextureSize) + " (GL_MAX_TEXTURE_SIZE)";
    if (has_layers) o.fail("raw_size", "raw bytes come in path or levels (every layer of a level in one file), not layers");
    // [width, height], and for an array its layers.
    if (!size.is_array() || size.size() != (t.array ? 3u : 2u) || !within(size[0], texture::kMaxTextureSize) ||
        !within(size[1], texture::kMaxTextureSize) || (t.array && !within(size[2], texture::kMaxArrayLayers)))
      o.fail("raw_size", t.array ? "expected [width, height, layers], " + sides + " and layers from 1 to " +
                                       std::to_string(texture::kMaxArrayLayers) + " (GL_MAX_ARRAY_TEXTURE_LAYERS), got " +
                                       describe_json(size)
                                 : "expected [width, height], " + sides + ", got " + describe_json(size));
    if (!t.format) o.fail("raw_size", "raw texel bytes need the internalformat that lays them out");
    t.raw_size = std::array<int, 3>{size[0].get<int>(), size[1].get<int>(), t.array ? size[2].get<int>() : 1};
  }
  if (t.array && !has_layers && !t.raw_size)
    o.fail(has_path ? "path" : "levels", "a GL_TEXTURE_2D_ARRAY's image files are its layers: give layers (level 0's), "
                                         "or raw bytes of every layer with raw_size [width, height, layers]");
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
