// The image I/O module (libtessref_image_io.so): image files through OpenImageIO behind the C
// table of io/image_io_module.h. Built as a CMake MODULE, not part of tessref_pipeline;
// io/image_output.cpp loads it on first use.
#include "io/image_io_module.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

namespace {

thread_local std::string last_error;

const char* fail(std::string message) {
  last_error = std::move(message);
  return last_error.c_str();
}

OIIO::TypeDesc type_desc(tessref_image_io_type type) {
  return type == TESSREF_IMAGE_IO_FLOAT ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
}

std::size_t type_size(tessref_image_io_type type) {
  return type == TESSREF_IMAGE_IO_FLOAT ? sizeof(float) : 1;
}

// Runs body, turning an escaping exception into an error message naming the file.
template <typename Body>
const char* guarded(const char* path, Body&& body) {
  try {
    return body();
  } catch (const std::exception& e) {
    return fail(std::string(path) + ": image I/O failed: " + e.what());
  } catch (...) {
    return fail(std::string(path) + ": image I/O failed");
  }
}

const char* probe(const char* probe_path, int channels, tessref_image_io_type type, int* stored_float) {
  return guarded(probe_path, [&]() -> const char* {
    const std::string name = probe_path;
    auto out = OIIO::ImageOutput::create(name);
    if (!out) {
      (void)OIIO::geterror();  // names the scratch file: the caller says what failed
      return fail("OpenImageIO has no writer for this extension");
    }
    const OIIO::ImageSpec spec(1, 1, channels, type_desc(type));
    const bool opened = out->open(name, spec);
    // The writer may store another data type than asked (PNG: 8 or 16 bits for float data).
    const OIIO::TypeDesc stored = out->spec().format;
    const std::string why = opened ? std::string() : out->geterror();
    if (opened) {
      const std::vector<float> pixel(std::size_t(channels), 0.0f);
      out->write_image(OIIO::TypeDesc::FLOAT, pixel.data());
      out->close();
    }
    out.reset();
    std::remove(probe_path);
    if (!opened) return fail(why.empty() ? std::string("the writer refused it") : why);
    *stored_float = stored.basetype == OIIO::TypeDesc::FLOAT || stored.basetype == OIIO::TypeDesc::HALF;
    return nullptr;
  });
}

// "openexr:exr,sxr,mxr;png:png;..." from OpenImageIO, keeping the formats that have a writer.
const char* writable_extensions() {
  static const std::string list = [] {
    const std::string writers = "," + std::string(OIIO::get_string_attribute("output_format_list")) + ",";
    std::string out;
    const std::string all(OIIO::get_string_attribute("extension_list"));
    for (std::size_t start = 0; start < all.size();) {
      std::size_t end = all.find(';', start);
      if (end == std::string::npos) end = all.size();
      const std::string entry = all.substr(start, end - start);
      start = end + 1;
      const std::size_t colon = entry.find(':');
      if (colon == std::string::npos || writers.find("," + entry.substr(0, colon) + ",") == std::string::npos)
        continue;
      std::string exts = entry.substr(colon + 1) + ",";
      for (std::size_t a = 0, b; (b = exts.find(',', a)) != std::string::npos; a = b + 1)
        if (b > a) out += (out.empty() ? "." : " .") + exts.substr(a, b - a);
    }
    return out;
  }();
  return list.c_str();
}

const char* write(const char* path, int width, int height, int channels, tessref_image_io_type type,
                  const void* pixels, const char* const* channel_names) {
  return guarded(path, [&]() -> const char* {
    const std::string name = path;
    auto out = OIIO::ImageOutput::create(name);
    if (!out) return fail(name + ": cannot write this image format (" + OIIO::geterror() + ")");
    OIIO::ImageSpec spec(width, height, channels, type_desc(type));
    if (channel_names) spec.channelnames.assign(channel_names, channel_names + channels);
    // OpenImageIO stamps the current time into EXR and TIFF headers unless the spec names one:
    // name a fixed one there, so that the same frame gives the same bytes on any day. (Other
    // writers add no time; giving them one would only add a metadata chunk.)
    const std::string format = out->format_name();
    if (format == "openexr" || format == "tiff") spec.attribute("DateTime", "1970:01:01 00:00:00");
    if (!out->open(name, spec)) return fail(name + ": cannot open for writing: " + out->geterror());
    bool ok = out->write_image(type_desc(type), pixels);
    ok = out->close() && ok;
    if (!ok) return fail(name + ": cannot write: " + out->geterror());
    return nullptr;
  });
}

const char* read(const char* path, tessref_image_io_type type, int channels,
                 tessref_image_io_alloc_fn alloc, void* context) {
  return guarded(path, [&]() -> const char* {
    const std::string name = path;
    // The values as stored: OpenImageIO premultiplies the colour of a file with straight alpha
    // (PNG, TIFF) by default, which no GL upload does; a framebuffer saved by a driver would come
    // back darker wherever its alpha is below 1.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(name, &config);
    if (!in) return fail(name + ": cannot read image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    const int stored = channels > 0 ? channels : spec.nchannels;
    const int wanted = std::min(stored, spec.nchannels);
    void* pixels = alloc(context, spec.width, spec.height, stored);
    if (!pixels) return fail(name + ": cannot read image: out of memory");
    const OIIO::stride_t xstride = OIIO::stride_t(stored * type_size(type));
    bool ok = in->read_image(0, 0, 0, wanted, type_desc(type), pixels, xstride,
                             xstride * spec.width);
    in->close();
    if (!ok) return fail(name + ": cannot read image: " + in->geterror());
    return nullptr;
  });
}

const char* diff(const char* a, const char* b, double warn_threshold, double fail_threshold,
                 const char* diff_path, double diff_scale, tessref_image_io_diff* out) {
  return guarded(a, [&]() -> const char* {
    OIIO::ImageBuf A(a), B(b);
    if (!A.read(0, 0, true, OIIO::TypeDesc::FLOAT)) return fail(std::string(a) + ": cannot read image: " + A.geterror());
    if (!B.read(0, 0, true, OIIO::TypeDesc::FLOAT)) return fail(std::string(b) + ": cannot read image: " + B.geterror());
    const OIIO::ImageSpec &sa = A.spec(), &sb = B.spec();
    if (sa.width != sb.width || sa.height != sb.height)
      return fail(std::string(a) + " is " + std::to_string(sa.width) + "x" + std::to_string(sa.height) + ", " + b +
                  " is " + std::to_string(sb.width) + "x" + std::to_string(sb.height) + ": nothing to compare");
    OIIO::ROI roi = A.roi();
    roi.chend = std::min(sa.nchannels, sb.nchannels);
    // One pass per threshold: compare() counts a pixel under one of its two thresholds only.
    const auto warn = OIIO::ImageBufAlgo::compare(A, B, warn_threshold, warn_threshold, roi);
    const auto over = OIIO::ImageBufAlgo::compare(A, B, fail_threshold, fail_threshold, roi);
    // (Their `error` flags are set whenever a pixel is over the fail threshold in OpenImageIO 2.4;
    // what could make the comparison itself fail, unread files or unequal sizes, is checked above.)
    *out = tessref_image_io_diff{sa.width, sa.height, roi.chend, warn.meanerror, warn.rms_error, warn.PSNR,
                                 warn.maxerror, warn.maxx, warn.maxy, warn.maxc, uint64_t(warn.nfail),
                                 uint64_t(over.nfail)};
    if (diff_path) {
      OIIO::ImageBuf d = OIIO::ImageBufAlgo::mul(OIIO::ImageBufAlgo::absdiff(A, B, roi), float(diff_scale));
      if (d.has_error()) return fail(std::string(diff_path) + ": cannot make the difference image: " + d.geterror());
      OIIO::ImageSpec& spec = d.specmod();
      const std::string ext = OIIO::Filesystem::extension(diff_path);
      if (ext == ".exr" || ext == ".tif" || ext == ".tiff") spec.attribute("DateTime", "1970:01:01 00:00:00");
      if (!d.write(diff_path)) return fail(std::string(diff_path) + ": cannot write: " + d.geterror());
    }
    return nullptr;
  });
}

const char* channel_names(const char* path, const char** names) {
  return guarded(path, [&]() -> const char* {
    thread_local std::string joined;
    auto in = OIIO::ImageInput::open(path);
    if (!in) return fail(std::string(path) + ": cannot read image: " + OIIO::geterror());
    joined.clear();
    for (const std::string& n : in->spec().channelnames) joined += (joined.empty() ? "" : "\n") + n;
    in->close();
    *names = joined.c_str();
    return nullptr;
  });
}

const char* stored_format(const char* path, int* bits, int* is_float) {
  return guarded(path, [&]() -> const char* {
    auto in = OIIO::ImageInput::open(path);
    if (!in) return fail(std::string(path) + ": cannot read image: " + OIIO::geterror());
    const OIIO::TypeDesc f = in->spec().format;
    *bits = int(f.basesize() * 8);
    *is_float = f.is_floating_point() ? 1 : 0;
    in->close();
    return nullptr;
  });
}

const tessref_image_io_api kApi = {TESSREF_IMAGE_IO_ABI_VERSION, sizeof(tessref_image_io_api),
                                   probe, writable_extensions, write, diff, read, channel_names, stored_format};

}  // namespace

extern "C" __attribute__((visibility("default"))) const tessref_image_io_api*
tessref_image_io_api_v1(void) {
  return &kApi;
}
