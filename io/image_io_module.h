#pragma once
// The C interface between io/image_output.cpp and the image I/O module
// (io/image_io_module.cpp, built as the shared module libtessref_image_io.so).
//
// OpenImageIO pulls in some 260 shared libraries; resolving them costs a quarter of a second at
// start-up. So only the module links it, and image_output.cpp dlopens the module on the first
// image read or write that needs it: commands that write no image, or only 8-bit PNGs
// (io/png_writer.h), never load OpenImageIO.
//
// The module exports one symbol, TESSREF_IMAGE_IO_ENTRY, a function that returns the table
// below. Nothing but plain C types crosses the boundary, and no exception does.
#include <stdint.h>

#define TESSREF_IMAGE_IO_ABI_VERSION 4u
#define TESSREF_IMAGE_IO_ENTRY "tessref_image_io_api_v1"
#define TESSREF_IMAGE_IO_MODULE_NAME "libtessref_image_io.so"

extern "C" {

enum tessref_image_io_type : int32_t { TESSREF_IMAGE_IO_UINT8 = 0, TESSREF_IMAGE_IO_FLOAT = 1 };

// Called by read once the image's size is known: returns a zero-filled buffer of
// width * height * channels elements of the requested type, or null (out of memory).
typedef void* (*tessref_image_io_alloc_fn)(void* context, int width, int height, int channels);

// What diff found (ImageBufAlgo::compare over the channels both images have).
struct tessref_image_io_diff {
  int width, height, channels;
  double mean_error, rms_error, psnr, max_error;
  int max_x, max_y, max_c;      // where max_error is (max_y counted from the top row)
  uint64_t over_warn, over_fail;  // pixels with a channel difference above warn / fail threshold
};

// Each function returns null on success, or an error message that names the file (valid until
// the next call on the same thread).
struct tessref_image_io_api {
  uint32_t abi_version;  // TESSREF_IMAGE_IO_ABI_VERSION
  uint32_t size;         // sizeof(tessref_image_io_api)
  // Asks the writer for probe_path's extension whether it can store `channels` channels of
  // `type`: opens probe_path (a scratch file, removed again) for a 1x1 image as write() would.
  // On success *stored_float says whether the writer keeps float data as floating point (PNG
  // would quantize it). Fails when there is no writer for the extension or it refuses the spec.
  const char* (*probe)(const char* probe_path, int channels, tessref_image_io_type type,
                       int* stored_float);
  // The file extensions this OpenImageIO can write, space-separated, with dots (".exr .png").
  const char* (*writable_extensions)(void);
  // Pixels top row first, channels interleaved; channel_names: `channels` names, or null.
  const char* (*write)(const char* path, int width, int height, int channels,
                       tessref_image_io_type type, const void* pixels,
                       const char* const* channel_names);
  // Compares two images of the same size; writes |a - b| * diff_scale to diff_path unless null.
  const char* (*diff)(const char* a, const char* b, double warn_threshold, double fail_threshold,
                      const char* diff_path, double diff_scale, tessref_image_io_diff* out);
  // Reads the first subimage converted to `type`. channels > 0: a buffer of that many channels
  // per pixel receives the file's first min(channels, file channels) (the rest stay 0);
  // channels == 0: every channel of the file.
  const char* (*read)(const char* path, tessref_image_io_type type, int channels,
                      tessref_image_io_alloc_fn alloc, void* context);
  // The first subimage's channel names in the order read() delivers them (OpenImageIO's, which
  // for OpenEXR is not the order written), '\n'-separated, in *names (valid until the next call
  // on the same thread).
  const char* (*channel_names)(const char* path, const char** names);
  // How the first subimage stores its values: *is_float 1 for floating point, else unsigned
  // integers of *bits bits (8, 16, 32) that read() scales to [0, 1].
  const char* (*stored_format)(const char* path, int* bits, int* is_float);
};

typedef const tessref_image_io_api* (*tessref_image_io_entry_fn)(void);
// The entry point, named TESSREF_IMAGE_IO_ENTRY (defined only in the module).
const tessref_image_io_api* tessref_image_io_api_v1(void);

}  // extern "C"
