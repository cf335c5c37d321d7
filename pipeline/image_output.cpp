#include "pipeline/image_output.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <OpenImageIO/imageio.h>

#include "common/error.h"

namespace tessref {
namespace {

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// Writes rows top first from a buffer that is already top first.
void write_image(const std::filesystem::path& path, int width, int height, int channels,
                 OIIO::TypeDesc type, const void* data,
                 const std::vector<std::string>& channel_names = {}) {
  const std::string name = path.string();
  auto out = OIIO::ImageOutput::create(name);
  if (!out)
    throw InputError(name + ": cannot write this image format (" + OIIO::geterror() + ")");
  OIIO::ImageSpec spec(width, height, channels, type);
  if (!channel_names.empty()) spec.channelnames = channel_names;
  if (!out->open(name, spec)) throw InputError(name + ": cannot open for writing: " + out->geterror());
  bool ok = out->write_image(type, data);
  ok = out->close() && ok;
  if (!ok) throw InputError(name + ": cannot write: " + out->geterror());
}

// Copies a bottom-first framebuffer attachment into a top-first float buffer.
template <typename Get>
std::vector<float> flipped(const Framebuffer& fb, int channels, Get&& get) {
  std::vector<float> rows(std::size_t(fb.width) * fb.height * channels);
  for (int y = 0; y < fb.height; ++y) {
    float* dst = &rows[std::size_t(fb.height - 1 - y) * fb.width * channels];
    for (int x = 0; x < fb.width; ++x) get(fb.index(x, y), dst + std::size_t(x) * channels);
  }
  return rows;
}

void require_float_format(const std::filesystem::path& path, const char* what) {
  if (!is_float_format(path))
    throw InputError(path.string() + ": " + what +
                     " need a floating-point format: .exr, .tif, .tiff, .pfm or .hdr");
}

std::uint8_t unorm8(float c) {
  if (!(c > 0.0f)) return 0;  // also NaN
  if (c >= 1.0f) return 255;
  return static_cast<std::uint8_t>(c * 255.0f + 0.5f);
}

}  // namespace

Rgb8Image to_rgb8(const Framebuffer& fb) {
  Rgb8Image img{fb.width, fb.height, std::vector<std::uint8_t>(std::size_t(fb.width) * fb.height * 3)};
  for (int y = 0; y < fb.height; ++y) {
    std::uint8_t* dst = &img.pixels[std::size_t(fb.height - 1 - y) * fb.width * 3];
    for (int x = 0; x < fb.width; ++x) {
      const glm::vec4& c = fb.color[fb.index(x, y)];
      for (int k = 0; k < 3; ++k) dst[3 * x + k] = unorm8(c[k]);
    }
  }
  return img;
}

bool is_float_format(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  return ext == ".exr" || ext == ".hdr" || ext == ".pfm" || ext == ".tif" || ext == ".tiff";
}

void check_image_path(const std::filesystem::path& path, bool float_only, const char* what) {
  if (float_only) require_float_format(path, what);
  if (!OIIO::ImageOutput::create(path.string()))
    throw InputError(path.string() + ": cannot write this image format (" + OIIO::geterror() + ")");
}

void write_color_image(const Framebuffer& fb, const std::filesystem::path& path) {
  if (!is_float_format(path)) return write_rgb8_image(to_rgb8(fb), path);
  const bool rgb_only = lower_extension(path) == ".hdr" || lower_extension(path) == ".pfm";
  const int channels = rgb_only ? 3 : 4;
  std::vector<float> rows = flipped(fb, channels, [&](std::size_t i, float* dst) {
    for (int k = 0; k < channels; ++k) dst[k] = fb.color[i][k];
  });
  write_image(path, fb.width, fb.height, channels, OIIO::TypeDesc::FLOAT, rows.data());
}

void write_depth_image(const Framebuffer& fb, const std::filesystem::path& path) {
  require_float_format(path, "depth images");
  std::vector<float> rows = flipped(fb, 1, [&](std::size_t i, float* dst) { dst[0] = fb.depth[i]; });
  write_image(path, fb.width, fb.height, 1, OIIO::TypeDesc::FLOAT, rows.data(), {"Z"});
}

void write_normals_image(const Framebuffer& fb, const std::filesystem::path& path) {
  require_float_format(path, "normal images");
  std::vector<float> rows = flipped(fb, 3, [&](std::size_t i, float* dst) {
    for (int k = 0; k < 3; ++k) dst[k] = fb.aux[i][k];
  });
  write_image(path, fb.width, fb.height, 3, OIIO::TypeDesc::FLOAT, rows.data());
}

void write_rgb8_image(const Rgb8Image& image, const std::filesystem::path& path) {
  write_image(path, image.width, image.height, 3, OIIO::TypeDesc::UINT8, image.pixels.data());
}

Rgb8Image read_rgb8_image(const std::filesystem::path& path) {
  const std::string name = path.string();
  auto in = OIIO::ImageInput::open(name);
  if (!in) throw InputError(name + ": cannot read image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  Rgb8Image img{spec.width, spec.height,
                std::vector<std::uint8_t>(std::size_t(spec.width) * spec.height * 3)};
  // Channels 0..2 as 8 bits (a gray image is read into the first channel only).
  bool ok = in->read_image(0, 0, 0, std::min(3, spec.nchannels), OIIO::TypeDesc::UINT8,
                           img.pixels.data(), 3, OIIO::stride_t(spec.width) * 3);
  in->close();
  if (!ok) throw InputError(name + ": cannot read image: " + in->geterror());
  return img;
}

FloatImage read_float_image(const std::filesystem::path& path) {
  const std::string name = path.string();
  auto in = OIIO::ImageInput::open(name);
  if (!in) throw InputError(name + ": cannot read image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  FloatImage img{spec.width, spec.height, spec.nchannels,
                 std::vector<float>(std::size_t(spec.width) * spec.height * spec.nchannels)};
  bool ok = in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, img.pixels.data());
  in->close();
  if (!ok) throw InputError(name + ": cannot read image: " + in->geterror());
  return img;
}

}  // namespace tessref
