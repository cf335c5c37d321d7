#include "render/initial_images.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/error.h"
#include "io/image_output.h"

namespace tessref {
namespace {

// The file as rows from the bottom, checked against the image's size.
FloatImage read_bottom_up(const Scene& scene, const std::filesystem::path& file, const char* key) {
  FloatImage image;
  try {
    image = read_float_image(file);
  } catch (const InputError& e) {
    throw InputError(scene.source + ": " + key + ": " + e.what());
  }
  if (image.width != scene.width || image.height != scene.height)
    throw InputError(scene.source + ": " + key + ": '" + file.string() + "' is " + std::to_string(image.width) + "x" +
                     std::to_string(image.height) + ", the image " + std::to_string(scene.width) + "x" +
                     std::to_string(scene.height));
  const std::size_t row = std::size_t(image.width) * std::size_t(image.channels);
  for (int y = 0; y < image.height / 2; ++y)
    std::swap_ranges(image.pixels.begin() + std::ptrdiff_t(y * row), image.pixels.begin() + std::ptrdiff_t((y + 1) * row),
                     image.pixels.begin() + std::ptrdiff_t((image.height - 1 - y) * row));
  return image;
}

}  // namespace

InitialPixels load_initial_images(const Scene& scene) {
  InitialPixels out;
  const FramebufferSetting& f = scene.framebuffer;
  for (std::size_t k = 0; k < f.color.size(); ++k) {
    std::optional<std::vector<glm::vec4>>& slot = out.color.emplace_back();
    if (f.color[k].file.empty()) continue;
    const std::string key = "framebuffer.color." + std::to_string(k);
    const FloatImage im = read_bottom_up(scene, f.color[k].file, key.c_str());
    const std::size_t c = std::size_t(im.channels);
    std::vector<glm::vec4>& color = slot.emplace(std::size_t(im.width) * std::size_t(im.height));
    for (std::size_t i = 0; i < color.size(); ++i) {
      const float* p = im.pixels.data() + i * c;
      // Gray, gray + alpha, RGB, RGBA, as load_texture reads them.
      const float r = p[0], g = c >= 3 ? p[1] : p[0], b = c >= 3 ? p[2] : p[0];
      const float a = c == 2 ? p[1] : c >= 4 ? p[3] : 1.0f;
      // The values are what the attachment holds: no sRGB encoding, only the format's rounding.
      color[i] = stored_color(f.color[k].format, false, glm::vec4(r, g, b, a));
    }
  }
  if (!f.depth_file.empty()) {
    const FloatImage im = read_bottom_up(scene, f.depth_file, "framebuffer.depth");
    std::vector<float>& depth = out.depth.emplace(std::size_t(im.width) * std::size_t(im.height));
    for (std::size_t i = 0; i < depth.size(); ++i) {
      const float z = im.pixels[i * std::size_t(im.channels)];
      if (!(z >= 0.0f && z <= 1.0f))
        throw InputError(scene.source + ": framebuffer.depth: '" + f.depth_file.string() + "' holds " +
                         std::to_string(z) + " at pixel " + std::to_string(i % std::size_t(im.width)) + ", row " +
                         std::to_string(i / std::size_t(im.width)) + " from the bottom; a depth buffer holds [0, 1]");
      depth[i] = stored_depth(f.depth_format, z);
    }
  }
  return out;
}

void set_up_framebuffer(const Scene& scene, const InitialPixels& images, Framebuffer& fb) {
  const FramebufferSetting& f = scene.framebuffer;
  fb.set_draw_buffers(std::max<int>(2, int(f.color.size())));
  for (std::size_t k = 0; k < f.color.size(); ++k) fb.color_format[k] = f.color[k].format;
  fb.depth_format = f.depth_format;
  for (int k = 0; k < int(f.color.size()); ++k) {
    std::vector<glm::vec4>& b = *fb.draw_buffer(k);
    const std::optional<std::vector<glm::vec4>>& image = images.color[std::size_t(k)];
    if (image) b = *image;
    else std::fill(b.begin(), b.end(), stored_color(f.color[std::size_t(k)].format, false, scene.background));
  }
  if (images.depth) fb.depth = *images.depth;
}

}  // namespace tessref
