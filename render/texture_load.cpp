#include "render/texture_load.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>

#include "common/error.h"
#include "io/image_output.h"
#include "render/buffer_load.h"
#include "texture/mipmap.h"

namespace tessref {
namespace {

const char* channels_name(int channels) {
  switch (channels) {
    case 1: return "gray (1 channel)";
    case 2: return "gray and alpha (2 channels)";
    case 3: return "RGB (3 channels)";
    default: return "RGBA (4 channels)";
  }
}

// An image's pixels as RGBA rows from the bottom (GL's order): gray repeated in R, G and B
// (GL_RGBA32F from a gray file) or kept in R (an R format), alpha 1 where the file has none.
std::vector<float> rgba_rows(const FloatImage& image, bool gray_to_rgb) {
  std::vector<float> out(std::size_t(image.width) * std::size_t(image.height) * 4);
  const int ch = image.channels;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float* src = image.pixels.data() + (std::size_t(image.height - 1 - y) * std::size_t(image.width) + std::size_t(x)) * std::size_t(ch);
      float* dst = out.data() + (std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4;
      if (ch <= 2) {
        dst[0] = src[0];
        dst[1] = gray_to_rgb ? src[0] : ch == 2 ? src[1] : 0.0f;
        dst[2] = gray_to_rgb ? src[0] : 0.0f;
        dst[3] = ch == 2 && gray_to_rgb ? src[1] : 1.0f;
      } else {
        for (int c = 0; c < 4; ++c) dst[c] = c < ch ? src[c] : 1.0f;
      }
    }
  return out;
}

// An integer format's texels from an image file (GL uploads them as integers, GL 4.6 8.4.4.2):
// an 8- or 16-bit file's stored integers k (read as k / (2^b - 1)), a float file's values, which
// must be whole numbers; each within the format's range.
std::vector<std::int64_t> integer_texels(const FloatImage& image, const std::vector<float>& rgba,
                                         const texture::TexelFormatInfo& format, const std::filesystem::path& file,
                                         const std::string& at) {
  const double scale = image.stored_float ? 1.0 : std::ldexp(1.0, image.stored_bits) - 1.0;
  std::vector<std::int64_t> out(rgba.size());
  for (std::size_t k = 0; k < rgba.size(); ++k) {
    const double v = double(rgba[k]) * scale;
    const int c = int(k % 4);
    if (c >= format.channels) {  // not stored: alpha 1 and 0 for the others, as decoded
      out[k] = c == 3 ? 1 : 0;
      continue;
    }
    const double whole = std::nearbyint(v);
    if (!(std::fabs(v - whole) <= (image.stored_float ? 0.0 : 1e-3)) || whole < double(format.integer_min(c)) ||
        whole > double(format.integer_max(c))) {
      const std::size_t texel = k / 4;
      const std::size_t x = texel % std::size_t(image.width), y = std::size_t(image.height) - 1 - texel / std::size_t(image.width);
      char value[64];
      std::snprintf(value, sizeof value, "%.9g", v);
      throw InputError(at + ": " + file.string() + " pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                       ") channel " + std::to_string(c) + " is " + value + ", and " + format.gl_name +
                       " holds whole numbers from " + std::to_string(format.integer_min(c)) + " to " +
                       std::to_string(format.integer_max(c)) + " (internalformat; give a float file of whole "
                       "numbers, an 8/16-bit file's integers, or raw bytes with raw_size)");
    }
    out[k] = std::int64_t(whole);
  }
  return out;
}

// Level k of a texture whose level 0 is w x h with `layers` layers, from a file of raw texel
// bytes in format f.
texture::Level read_raw_level(const std::filesystem::path& file, texture::TexelFormat f, std::array<int, 3> size0, int k,
                              bool three_d, const std::string& at) {
  const texture::TexelFormatInfo& fi = texture::info(f);
  const int w = size0[0], h = size0[1], d = three_d ? size0[2] : 1;
  if (k > 0 && std::max({w, h, d}) >> k == 0)
    throw InputError(at + ": a " + std::to_string(w) + "x" + std::to_string(h) + (three_d ? "x" + std::to_string(d) : "") +
                     " texture has no level " + std::to_string(k));
  // A 3D texture's depth halves with each level; an array keeps its layers.
  const int width = std::max(1, w >> k), height = std::max(1, h >> k), layers = three_d ? std::max(1, d >> k) : size0[2];
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(at + ": cannot open " + file.string());
  std::vector<std::uint8_t> stored{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const std::size_t want = std::size_t(width) * std::size_t(height) * std::size_t(layers) * std::size_t(fi.bytes_per_texel());
  if (stored.size() != want)
    throw InputError(at + ": " + file.string() + " has " + std::to_string(stored.size()) + " bytes, and level " +
                     std::to_string(k) + " of " + fi.gl_name + " is " + std::to_string(width) + "x" + std::to_string(height) +
                     (layers > 1 ? "x" + std::to_string(layers) : "") + " texels of " + std::to_string(fi.bytes_per_texel()) +
                     " bytes: " + std::to_string(want) + " (raw_size)");
  // GL_DEPTH_COMPONENT24 words as GL_UNSIGNED_INT: the top 24 bits are the depth; the low byte is
  // made to repeat them, so the driver's conversion cannot round differently.
  if (f == texture::TexelFormat::kDepth24)
    for (std::size_t i = 0; i + 4 <= stored.size(); i += 4) {
      std::uint32_t word;
      std::memcpy(&word, &stored[i], 4);
      word = (word & 0xffffff00u) | (word >> 24);
      std::memcpy(&stored[i], &word, 4);
    }
  return texture::level_from_stored(f, width, height, layers, std::move(stored));
}

// One image file's texels for a texture of `format` (declared when `declared`), RGBA rows from the
// bottom: floats, or for an integer format integers (and no floats).
struct ImageTexels {
  int width = 0, height = 0;
  std::vector<float> rgba;
  std::vector<std::int64_t> integers;
};
ImageTexels read_image_texels(const std::filesystem::path& file, const texture::TexelFormatInfo& format, bool declared,
                              const std::string& at) {
  FloatImage image;
  try {
    image = read_float_image(file);
  } catch (const InputError& e) {
    throw InputError(at + ": " + e.what());
  }
  if (declared && image.channels != format.channels)
    throw InputError(at + ": " + file.string() + " is " + channels_name(image.channels) + ", and " + format.gl_name +
                     " has " + std::to_string(format.channels) + " channel" + (format.channels > 1 ? "s" : "") +
                     " (internalformat)");
  using texture::kMaxTextureSize;
  if (image.width > kMaxTextureSize || image.height > kMaxTextureSize)
    throw InputError(at + ": " + file.string() + " is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                     ", more than GL_MAX_TEXTURE_SIZE (" + std::to_string(kMaxTextureSize) + ")");
  ImageTexels out;
  out.width = image.width;
  out.height = image.height;
  out.rgba = rgba_rows(image, !declared);
  if (format.integer()) {
    out.integers = integer_texels(image, out.rgba, format, file, at);
    out.rgba = {};
  }
  return out;
}

// Layers of one level, each width x height, as a level of format f (one layer is not copied). A
// 1D array's level is one image whose rows are its layers (as glTexSubImage2D takes them).
texture::Level level_of_layers(texture::TexelFormat f, std::vector<ImageTexels> layers, bool rows_are_layers = false) {
  const int w = layers[0].width, h = rows_are_layers ? 1 : layers[0].height;
  const int n = rows_are_layers ? layers[0].height : int(layers.size());
  auto joined = [&](auto member) {
    auto all = std::move(layers[0].*member);
    for (std::size_t k = 1; k < layers.size(); ++k) all.insert(all.end(), (layers[k].*member).begin(), (layers[k].*member).end());
    return all;
  };
  if (texture::info(f).integer()) return texture::make_integer_level(f, w, h, joined(&ImageTexels::integers).data(), n);
  return texture::make_level(f, w, h, joined(&ImageTexels::rgba).data(), n);
}

// A buffer texture's one image (GL 4.6 8.9): the whole texels of its range, at most
// GL_MAX_TEXTURE_BUFFER_SIZE of them.
texture::Level buffer_texels(const TextureSetting& t, texture::TexelFormat f, const Scene& scene, const std::string& key) {
  const draw::Buffer buffer = load_buffer(scene.source, find_buffer(scene, t.buffer, key + ".buffer"));
  const std::size_t bytes = buffer.bytes.size();
  const std::string range = "buffers." + t.buffer + " has " + std::to_string(bytes) + " bytes";
  if (t.buffer_offset >= bytes)
    throw InputError(key + (t.buffer_offset ? ".offset: " + std::to_string(t.buffer_offset) + " is not inside the buffer: " : ".buffer: ") +
                     range + " (glTexBufferRange needs a range of at least one byte)");
  if (t.buffer_size && *t.buffer_size > bytes - t.buffer_offset)
    throw InputError(key + ".size: offset " + std::to_string(t.buffer_offset) + " + size " + std::to_string(*t.buffer_size) +
                     " is past the buffer's end: " + range + " (glTexBufferRange: GL_INVALID_VALUE)");
  const std::size_t size = t.buffer_size.value_or(bytes - t.buffer_offset);
  const std::size_t texel_bytes = std::size_t(texture::info(f).bytes_per_texel());
  const std::size_t texels = std::min<std::size_t>(size / texel_bytes, std::size_t(texture::kMaxTextureBufferSize));
  const auto* first = reinterpret_cast<const std::uint8_t*>(buffer.bytes.data()) + t.buffer_offset;
  return texture::level_from_stored(f, int(texels), 1, 1, std::vector<std::uint8_t>(first, first + texels * texel_bytes));
}

}  // namespace

texture::Texture load_texture(const TextureSetting& t, const std::string& key, const Scene& scene) {
  texture::Texture tex;
  tex.target = t.target;
  tex.format = t.format.value_or(texture::TexelFormat::kRgba32F);
  const texture::TexelFormatInfo& format = texture::info(tex.format);
  if (t.target == texture::Target::kBuffer) {
    tex.levels.push_back(buffer_texels(t, tex.format, scene, key));
    tex.finalize();
    return tex;
  }
  if (!t.layers.empty()) {  // a 2D array's level 0, one file per layer, or a 3D texture's per slice
    std::vector<ImageTexels> layers;
    for (std::size_t k = 0; k < t.layers.size(); ++k) {
      const std::string at = key + ".layers." + std::to_string(k);
      layers.push_back(read_image_texels(t.layers[k], format, t.format.has_value(), at));
      if (t.target == texture::Target::k3D && std::max(layers[k].width, layers[k].height) > texture::kMax3DTextureSize)
        throw InputError(at + ": " + t.layers[k].string() + " is " + std::to_string(layers[k].width) + "x" +
                         std::to_string(layers[k].height) + ", more than GL_MAX_3D_TEXTURE_SIZE (" +
                         std::to_string(texture::kMax3DTextureSize) + ")");
      if (layers[k].width != layers[0].width || layers[k].height != layers[0].height)
        throw InputError(at + ": " + t.layers[k].string() + " is " + std::to_string(layers[k].width) + "x" +
                         std::to_string(layers[k].height) + ", and layer 0 is " + std::to_string(layers[0].width) + "x" +
                         std::to_string(layers[0].height) + " (an array's layers are one size)");
    }
    // GL 4.6 8.5.3: GL_INVALID_VALUE for a cube map whose width is not its height.
    if (texture::is_cube(t.target) && layers[0].width != layers[0].height)
      throw InputError(key + ".layers.0: " + t.layers[0].string() + " is " + std::to_string(layers[0].width) + "x" +
                       std::to_string(layers[0].height) + ", and a cube map's faces are square");
    tex.levels.push_back(level_of_layers(tex.format, std::move(layers)));
  }
  const bool one_d = texture::dimensions(t.target) == 1, rows_are_layers = t.target == texture::Target::k1DArray;
  int width0 = 0, height0 = 0;
  for (std::size_t k = 0; k < t.levels.size(); ++k) {
    const std::string at = t.levels.size() > 1 ? key + ".levels." + std::to_string(k) : key;
    if (t.raw_size) {
      tex.levels.push_back(read_raw_level(t.levels[k], tex.format, *t.raw_size, int(k), t.target == texture::Target::k3D, at));
      continue;
    }
    std::vector<ImageTexels> level;  // one image
    level.push_back(read_image_texels(t.levels[k], format, t.format.has_value(), at));
    const ImageTexels& image = level[0];
    if (t.target == texture::Target::k1D && image.height != 1)
      throw InputError(at + ": " + t.levels[k].string() + " is " + std::to_string(image.width) + "x" +
                       std::to_string(image.height) + ", and a GL_TEXTURE_1D level is one row (an image of height 1)");
    if (k == 0) {
      width0 = image.width;
      height0 = image.height;
    }
    // glTexStorage* fixes level k's size from level 0's (GL 4.6 8.19): a 1D array keeps its layers.
    const int w = std::max(1, width0 >> k), h = rows_are_layers ? height0 : std::max(1, height0 >> k);
    const bool past_last = k > 0 && (one_d ? width0 : std::max(width0, height0)) >> k == 0;
    auto size = [](int x, int y) { return std::to_string(x) + "x" + std::to_string(y); };
    if (image.width != w || image.height != h || past_last)
      throw InputError(at + ": level " + std::to_string(k) + " is " + size(image.width, image.height) + ", and a level " +
                       std::to_string(k) + " of a " + size(width0, height0) + " texture is " +
                       (past_last ? std::string("past its last level") : size(w, h)) +
                       (rows_are_layers ? " (a 1D array's rows are its layers, in every level)" : ""));
    tex.levels.push_back(level_of_layers(tex.format, std::move(level), rows_are_layers));
  }
  // glGenerateMipmap right after level 0 is uploaded, before any glTexParameter: every level.
  if (t.generate_mipmaps) texture::generate_mipmaps(tex);
  tex.sampler = t.sampler_object.value_or(t.sampler_state);
  tex.base_level = t.base_level;
  tex.max_level = t.max_level;
  tex.swizzle = t.swizzle;
  tex.finalize();
  return tex;
}

}  // namespace tessref
