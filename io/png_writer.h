#pragma once
// 8-bit RGB PNG files written with libpng directly, without the image I/O module.
//
// Debian's OpenImageIO links every codec it supports (FFmpeg, OpenVDB, DCMTK, GDCM, libheif,
// LibRaw, OpenCV, ...) into libOpenImageIO.so itself, so loading it maps ~260 libraries and
// resolves their symbols: about 200 ms before the first pixel is written. A PNG needs none of
// them, and the default output of every command is a PNG, so this writer takes those files and
// the module stays for everything else (EXR, TIFF, reading, diff).
//
// The bytes are those of OpenImageIO 2.4's PNG writer, which uses the same libpng: colour type RGB,
// 8 bits, zlib level 6 with the default strategy, libpng's adaptive row filters, an oFFs chunk of
// (0, 0) pixels, nothing else. tests/io/png_writer_test.cpp checks that byte for byte.
#include <cstdint>
#include <filesystem>

namespace tessref {

// Pixels top row first, 3 bytes per pixel. InputError naming the file when it cannot be created
// or written whole (a full disk, a file size limit); the partial file is removed then.
void write_png_rgb8(const std::filesystem::path& path, int width, int height, const std::uint8_t* pixels);

}  // namespace tessref
