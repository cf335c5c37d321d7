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

// True for formats written as floating point: .exr, .hdr, .pfm, .tif, .tiff.
bool is_float_format(const std::filesystem::path& path);

// The color attachment; the format follows the extension: float RGBA for float formats
// (linear, unclamped), 8-bit RGB otherwise (to_rgb8). InputError naming the file on failure.
void write_color_image(const Framebuffer& fb, const std::filesystem::path& path);
// Window-space depth (one float channel "Z", 1 where nothing was drawn); float formats only.
void write_depth_image(const Framebuffer& fb, const std::filesystem::path& path);
// The aux attachment's xyz (the world normal the shaders write; 0 where nothing was drawn).
void write_normals_image(const Framebuffer& fb, const std::filesystem::path& path);

// Fails early (InputError naming the file) when OpenImageIO has no writer for the extension, or
// when float_only and the format is not a float format.
void check_image_path(const std::filesystem::path& path, bool float_only, const char* what);

// Float pixels as stored, top row first (channels per pixel as in the file).
struct FloatImage {
  int width = 0, height = 0, channels = 0;
  std::vector<float> pixels;
};
FloatImage read_float_image(const std::filesystem::path& path);  // InputError if unreadable

void write_rgb8_image(const Rgb8Image& image, const std::filesystem::path& path);
Rgb8Image read_rgb8_image(const std::filesystem::path& path);  // InputError if unreadable

// The path of the image I/O module in use (loads it first; InputError if it cannot).
std::string image_io_module_path();

}  // namespace tessref
