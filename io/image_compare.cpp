#include "io/image_compare.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "common/error.h"

namespace tessref {
namespace {

// covered(i): pixel i (top row first, as in Rgb8Image) holds geometry in a / in b.
template <typename CoveredA, typename CoveredB>
ImageComparison compare(const Rgb8Image& a, const Rgb8Image& b, CoveredA covered_a,
                        CoveredB covered_b, int tolerance, bool make_diff) {
  if (a.width != b.width || a.height != b.height)
    throw InputError("image comparison: sizes differ (" + std::to_string(a.width) + "x" +
                     std::to_string(a.height) + " and " + std::to_string(b.width) + "x" +
                     std::to_string(b.height) + ")");
  ImageComparison r;
  r.width = a.width;
  r.height = a.height;
  r.tolerance = tolerance;
  r.pixels = std::size_t(a.width) * a.height;
  if (make_diff) r.diff = Rgb8Image{a.width, a.height, std::vector<std::uint8_t>(r.pixels * 3, 0)};
  for (std::size_t i = 0; i < r.pixels; ++i) {
    int worst = 0;
    for (int k = 0; k < 3; ++k)
      worst = std::max(worst, std::abs(int(a.pixels[3 * i + k]) - int(b.pixels[3 * i + k])));
    r.max_difference = std::max(r.max_difference, worst);
    r.identical += worst == 0;
    r.within_tolerance += worst <= tolerance;
    const bool coverage_differs = covered_a(i) != covered_b(i);
    r.coverage_mismatch += coverage_differs;
    if (!make_diff) continue;
    std::uint8_t* d = &r.diff.pixels[3 * i];
    if (coverage_differs) {
      d[0] = 255;
    } else if (worst > tolerance) {
      for (int k = 0; k < 3; ++k)
        d[k] = std::uint8_t(std::min(255, 16 * std::abs(int(a.pixels[3 * i + k]) - int(b.pixels[3 * i + k]))));
    }
  }
  return r;
}

}  // namespace

std::string ImageComparison::summary() const {
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "%dx%d: %.4f%% of pixels within %d/255 (%.4f%% identical), max difference %d/255, "
                "%zu pixels covered in only one image",
                width, height, 100.0 * share_within(), tolerance,
                pixels ? 100.0 * double(identical) / double(pixels) : 100.0, max_difference,
                coverage_mismatch);
  return buf;
}

ImageComparison compare_framebuffers(const Framebuffer& a, const Framebuffer& b, int tolerance,
                                     bool make_diff) {
  if (a.depth.size() != std::size_t(a.width) * a.height || b.depth.size() != std::size_t(b.width) * b.height)
    throw InputError("image comparison: a framebuffer without depth");
  // Rgb8Image rows run top first; the framebuffers' bottom first.
  auto covered = [](const Framebuffer& fb) {
    return [&fb](std::size_t i) {
      const std::size_t row = i / fb.width, col = i % fb.width;
      return fb.depth[fb.index(int(col), fb.height - 1 - int(row))] < 1.0f;
    };
  };
  return compare(to_rgb8(a), to_rgb8(b), covered(a), covered(b), tolerance, make_diff);
}

ImageComparison compare_images(const Rgb8Image& a, const Rgb8Image& b, const glm::vec4& background,
                               int tolerance, bool make_diff) {
  // The background as the PNG writer stores it.
  const Rgb8Image bg = to_rgb8(Framebuffer(1, 1, background));
  auto covered = [&bg](const Rgb8Image& img) {
    return [&img, &bg](std::size_t i) {
      return img.pixels[3 * i] != bg.pixels[0] || img.pixels[3 * i + 1] != bg.pixels[1] ||
             img.pixels[3 * i + 2] != bg.pixels[2];
    };
  };
  return compare(a, b, covered(a), covered(b), tolerance, make_diff);
}

}  // namespace tessref
