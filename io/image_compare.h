#pragma once
// Comparing two renderings of one scene (tessref and a GL driver, or two PNG files) the way a
// viewer sees them: both quantized to 8 bits as the PNG writer does (to_rgb8), then per pixel.
#include <cstddef>
#include <filesystem>
#include <string>

#include <glm/glm.hpp>

#include "io/image_output.h"
#include "raster/framebuffer.h"

namespace tessref {

struct ImageComparison {
  int width = 0, height = 0;
  int tolerance = 2;                 // per channel, in 1/255 steps
  std::size_t pixels = 0;
  std::size_t within_tolerance = 0;  // every channel differs by <= tolerance
  std::size_t identical = 0;         // every channel equal
  int max_difference = 0;            // largest channel difference, 0..255
  std::size_t coverage_mismatch = 0; // covered in one image, background in the other
  Rgb8Image diff;                    // filled when asked for (see below)

  double share_within() const { return pixels ? double(within_tolerance) / double(pixels) : 1.0; }
  std::string summary() const;  // one line: shares, max difference, coverage mismatches
};

// The diff image: black where within tolerance, |difference| * 16 (clamped) elsewhere, pure red
// where coverage differs.
// Framebuffers: covered = depth < 1 (something was drawn). Both must have the same size.
ImageComparison compare_framebuffers(const Framebuffer& a, const Framebuffer& b, int tolerance = 2,
                                     bool make_diff = false);
// 8-bit images (e.g. PNG files): covered = the pixel differs from `background` quantized.
ImageComparison compare_images(const Rgb8Image& a, const Rgb8Image& b, const glm::vec4& background,
                               int tolerance = 2, bool make_diff = false);

}  // namespace tessref
