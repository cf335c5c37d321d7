#pragma once
// Framebuffer -> image files, through OpenImageIO in the image I/O module
// (libtessref_image_io.so, see image_io_module.h), which the first read or write loads. InputError
// naming the paths tried when the module cannot be found or loaded; TESSREF_IMAGE_IO_MODULE
// in the environment names the module's path.
// Files are written top row first: the framebuffer's row 0 (GL: bottom) becomes the last row.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "raster/framebuffer.h"

namespace tessref {

// 8-bit RGB, top row first (3 bytes per pixel).
struct Rgb8Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;
};

// Color to 8 bits as a GL UNORM8 attachment stores it: clamp to [0, 1] (NaN as 0), then
// round(c * 255). No sRGB encoding (the framebuffer holds what the shader wrote).
Rgb8Image to_rgb8(const Framebuffer& fb);

// What an image file holds: the colour attachment, depth (one float channel) or normals (three).
enum class ImageKind { Color, Depth, Normals };

// How the writer for a path's extension stores a kind of image, as OpenImageIO answers a probe
// (a 1x1 scratch file beside the path, removed again; answers are kept per extension).
struct ImageFormat {
  int channels = 3;           // colour: 4 (RGBA) where the writer takes them, else 3
  bool stores_float = false;  // floats kept as floats (.exr, .tif, .hdr, ...), not quantized
};

// Fails early (InputError naming the file) when this build's OpenImageIO has no writer for the
// extension or the writer cannot hold `kind` (depth and normals need floats; .hdr holds only 3
// channels), listing the extensions that can. Later writes to the same extension use the answer.
ImageFormat check_image_path(const std::filesystem::path& path, ImageKind kind);

// The extensions of the common image files this build can write `kind` to, space-separated
// (".exr .png ..."): for messages and --help.
std::string writable_image_extensions(ImageKind kind);

// The color attachment; the format follows the extension: float RGBA (or RGB) for formats that
// keep floats (linear, unclamped), 8-bit RGB otherwise (to_rgb8). InputError naming the file.
// draw_buffer: which of the framebuffer's draw buffers (0 is `color`; it must exist).
void write_color_image(const Framebuffer& fb, const std::filesystem::path& path, int draw_buffer = 0);
// Window-space depth (one float channel "Z", 1 where nothing was drawn); float formats only.
// Depth and normals check the format as check_image_path does.
void write_depth_image(const Framebuffer& fb, const std::filesystem::path& path);
// The aux attachment's xyz (the world normal the shaders write; 0 where nothing was drawn).
void write_normals_image(const Framebuffer& fb, const std::filesystem::path& path);
// Named float channels, interleaved, top row first (render --dump-fragments): written as given,
// for formats that keep floats and any number of channels (.exr). InputError naming the file.
void write_float_channels(const std::filesystem::path& path, int width, int height,
                          const std::vector<std::string>& channel_names, const std::vector<float>& pixels);

// Float pixels as stored, top row first (channels per pixel as in the file).
struct FloatImage {
  int width = 0, height = 0, channels = 0;
  std::vector<float> pixels;
  // How the file stores them: floats, or unsigned integers of stored_bits bits read as k / (2^b - 1).
  bool stored_float = true;
  int stored_bits = 32;
};
FloatImage read_float_image(const std::filesystem::path& path);  // InputError if unreadable
// The channel names of an image file in the order read_float_image delivers the channels.
std::vector<std::string> read_channel_names(const std::filesystem::path& path);

void write_rgb8_image(const Rgb8Image& image, const std::filesystem::path& path);
Rgb8Image read_rgb8_image(const std::filesystem::path& path);  // InputError if unreadable

// Two image files compared by OpenImageIO's ImageBufAlgo::compare over the channels both have, in
// the files' units (8-bit files as 0..1): `tessref diff`. Differences "above" a threshold are
// strictly greater. InputError when either cannot be read or their sizes differ.
struct ImageFileDiff {
  int width = 0, height = 0, channels = 0;
  double mean_error = 0, rms_error = 0, psnr = 0, max_error = 0;
  int max_x = 0, max_y = 0, max_channel = 0;  // max_y from the top row
  std::uint64_t above_warn = 0, above_fail = 0;  // pixels with a channel difference above each
};
// diff_path, when not empty: |a - b| * diff_scale written there (any format -o takes).
ImageFileDiff diff_image_files(const std::filesystem::path& a, const std::filesystem::path& b,
                               double warn_threshold, double fail_threshold,
                               const std::filesystem::path& diff_path = {}, double diff_scale = 1.0);

// The path of the image I/O module in use (loads it first; InputError if it cannot).
std::string image_io_module_path();

}  // namespace tessref
