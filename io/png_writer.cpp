#include "io/png_writer.h"

#include <png.h>
#include <zlib.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

#include "common/error.h"

namespace tessref {
namespace {

// libpng reports errors by longjmp; this state is all the encoder keeps across the jump, so
// nothing with a destructor lives in the frame that calls setjmp.
struct EncodeState {
  std::FILE* file = nullptr;
  bool write_failed = false;
  int write_errno = 0;  // errno of the failed write
  char message[256] = {};
};

void on_error(png_structp png, png_const_charp message) {
  auto* state = static_cast<EncodeState*>(png_get_error_ptr(png));
  std::snprintf(state->message, sizeof state->message, "%s", message ? message : "libpng error");
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}  // nothing the writer can do about one

void on_write(png_structp png, png_bytep data, std::size_t size) {
  auto* state = static_cast<EncodeState*>(png_get_io_ptr(png));
  if (std::fwrite(data, 1, size, state->file) != size) {
    state->write_failed = true;
    state->write_errno = errno;
    png_error(png, "write failed");
  }
}

void on_flush(png_structp png) {
  auto* state = static_cast<EncodeState*>(png_get_io_ptr(png));
  if (std::fflush(state->file) != 0) {
    state->write_failed = true;
    state->write_errno = errno;
    png_error(png, "write failed");
  }
}

// True when the whole image was encoded into state->file.
bool encode(EncodeState* state, int width, int height, const std::uint8_t* pixels) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, state, on_error, on_warning);
  if (!png) {
    std::snprintf(state->message, sizeof state->message, "out of memory");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    if (!info) std::snprintf(state->message, sizeof state->message, "out of memory");
    png_destroy_write_struct(&png, info ? &info : nullptr);
    return false;
  }
  png_set_write_fn(png, state, on_write, on_flush);
  png_set_compression_level(png, 6);
  png_set_compression_strategy(png, Z_DEFAULT_STRATEGY);
  png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_oFFs(png, info, 0, 0, PNG_OFFSET_PIXEL);
  png_write_info(png, info);
  const std::size_t row_bytes = std::size_t(width) * 3;
  for (int y = 0; y < height; ++y) png_write_row(png, pixels + std::size_t(y) * row_bytes);
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

void write_png_rgb8(const std::filesystem::path& path, int width, int height, const std::uint8_t* pixels) {
  if (width <= 0 || height <= 0)
    throw InputError(path.string() + ": cannot write a " + std::to_string(width) + "x" + std::to_string(height) +
                     " PNG (PNG images have at least one pixel)");
  EncodeState state;
  state.file = std::fopen(path.c_str(), "wb");
  if (!state.file)
    throw InputError(path.string() + ": cannot open for writing: " + std::strerror(errno));
  const bool encoded = encode(&state, width, height, pixels);
  const bool closed = std::fclose(state.file) == 0;
  if (encoded && closed) return;
  const int why = encoded ? errno : state.write_errno;
  std::error_code ec;
  std::string full;  // measured before the partial file is removed, which frees its blocks
  if (why == ENOSPC) {
    const auto space = std::filesystem::space(std::filesystem::absolute(path).parent_path(), ec);
    full = path.string() + ": the file system holding it is full (" +
           (ec ? std::string("no space") : std::to_string(space.available) + " bytes free") +
           "): the image was cut short";
  }
  if (std::filesystem::is_regular_file(std::filesystem::symlink_status(path, ec)))
    std::filesystem::remove(path, ec);  // never a device or what a link points at
  if (!encoded && !state.write_failed)
    throw InputError(path.string() + ": cannot write the PNG: " + state.message);
  if (!full.empty()) throw InputError(full);
  throw InputError(path.string() + ": cannot write: " + std::strerror(why));
}

}  // namespace tessref
