#include "io/image_output.h"

#include <dlfcn.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <map>
#include <mutex>
#include <new>
#include <string>
#include <system_error>

#include "common/error.h"
#include "io/image_io_module.h"
#include "io/png_writer.h"

namespace tessref {
namespace {

// Standard error sent to /dev/null for a scope: reading back a truncated PNG makes libpng print
// its own "IDAT: Read error" before tessref can say what happened in words.
class QuietStderr {
 public:
  QuietStderr() {
    std::fflush(stderr);
    saved_ = ::dup(2);
    const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (saved_ >= 0 && null >= 0) ::dup2(null, 2);
    if (null >= 0) ::close(null);
  }
  ~QuietStderr() {
    std::fflush(stderr);
    if (saved_ < 0) return;
    ::dup2(saved_, 2);
    ::close(saved_);
  }
  QuietStderr(const QuietStderr&) = delete;
  QuietStderr& operator=(const QuietStderr&) = delete;

 private:
  int saved_ = -1;
};

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// 8-bit PNG files are io/png_writer.h's, written without the module.
bool written_with_libpng(const std::filesystem::path& path) { return lower_extension(path) == ".png"; }

// The image I/O module (see image_io_module.h), loaded on first use. Where it is looked for:
//   1. $TESSREF_IMAGE_IO_MODULE, when set (then nowhere else);
//   2. <executable's folder>/TESSREF_IMAGE_IO_EXE_RELATIVE: the installed layout (bin/ and
//      lib/tessref/), which the build tree mirrors (cli/ and lib/tessref/);
//   3. the library search path (dlopen of the bare name): the executable's RUNPATH, which
//      find_package(tessref) adds for consumers, and LD_LIBRARY_PATH;
//   4. TESSREF_IMAGE_IO_BUILD_PATH: where this build tree put it;
//   5. TESSREF_IMAGE_IO_INSTALL_PATH: where `cmake --install` puts it by default.
struct ImageIoModule {
  const tessref_image_io_api* api = nullptr;
  std::string path;
};

// Checks the table of a dlopened module; InputError naming the path when it is not usable.
ImageIoModule checked_module(void* handle, const std::string& path) {
  // Never dlclosed: OpenImageIO keeps threads and static state for the life of the process.
  auto entry = reinterpret_cast<tessref_image_io_entry_fn>(::dlsym(handle, TESSREF_IMAGE_IO_ENTRY));
  const tessref_image_io_api* api = entry ? entry() : nullptr;
  if (!api)
    throw InputError("cannot load the image I/O module " + path + ": it has no " TESSREF_IMAGE_IO_ENTRY);
  if (api->abi_version != TESSREF_IMAGE_IO_ABI_VERSION || api->size < sizeof(tessref_image_io_api))
    throw InputError("cannot load the image I/O module " + path +
                     ": it is from another version of tessref");
  Dl_info info{};
  if (::dladdr(reinterpret_cast<const void*>(entry), &info) && info.dli_fname && *info.dli_fname)
    return {api, info.dli_fname};
  return {api, path};
}

ImageIoModule open_module(const std::string& path) {
  void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = ::dlerror();
    throw InputError("cannot load the image I/O module " + path + ": " + (why ? why : "dlopen failed"));
  }
  return checked_module(handle, path);
}

bool is_file(const std::string& path) {
  std::error_code ec;
  return !path.empty() && std::filesystem::is_regular_file(path, ec);
}

ImageIoModule find_module() {
  if (const char* env = std::getenv("TESSREF_IMAGE_IO_MODULE"); env && *env) {
    if (!is_file(env))
      throw InputError(std::string("cannot load the image I/O module ") + env +
                       " (from TESSREF_IMAGE_IO_MODULE): no such file");
    return open_module(env);
  }
  std::vector<std::string> tried;
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const std::string path = (exe.parent_path() / TESSREF_IMAGE_IO_EXE_RELATIVE /
                              TESSREF_IMAGE_IO_MODULE_NAME).lexically_normal().string();
    if (is_file(path)) return open_module(path);
    tried.push_back(path);
  }
  if (void* handle = ::dlopen(TESSREF_IMAGE_IO_MODULE_NAME, RTLD_NOW | RTLD_LOCAL))
    return checked_module(handle, TESSREF_IMAGE_IO_MODULE_NAME);
  tried.push_back(std::string(TESSREF_IMAGE_IO_MODULE_NAME) + " on the library search path");
  for (const std::string path : {TESSREF_IMAGE_IO_BUILD_PATH, TESSREF_IMAGE_IO_INSTALL_PATH}) {
    if (is_file(path)) return open_module(path);
    tried.push_back(path);
  }
  std::string list;
  for (const std::string& t : tried) list += (list.empty() ? "" : ", ") + t;
  throw InputError("cannot find the image I/O module (tried " + list +
                   "); set TESSREF_IMAGE_IO_MODULE to the path of " TESSREF_IMAGE_IO_MODULE_NAME);
}

const ImageIoModule& loaded_module() {
  static const ImageIoModule module = find_module();  // a throw leaves it for the next call
  return module;
}

const tessref_image_io_api& image_io() { return *loaded_module().api; }

void check(const char* error) {
  if (error) throw InputError(error);
}

// Writes rows top first from a buffer that is already top first.
void write_image(const std::filesystem::path& path, int width, int height, int channels,
                 tessref_image_io_type type, const void* data,
                 const std::vector<const char*>& channel_names = {}) {
  check(image_io().write(path.string().c_str(), width, height, channels, type, data,
                         channel_names.empty() ? nullptr : channel_names.data()));
}

// Reads into a vector of T resized by the module's alloc call.
template <typename T>
struct ReadTarget {
  std::vector<T>* pixels;
  int width = 0, height = 0, channels = 0;
  static void* alloc(void* context, int width, int height, int channels) {
    auto* self = static_cast<ReadTarget*>(context);
    if (width < 0 || height < 0 || channels < 0) return nullptr;
    try {
      self->pixels->assign(std::size_t(width) * std::size_t(height) * std::size_t(channels), T{});
    } catch (const std::bad_alloc&) {
      return nullptr;
    } catch (const std::length_error&) {
      return nullptr;
    }
    self->width = width;
    self->height = height;
    self->channels = channels;
    // Non-null even for an empty image (null means out of memory); nothing is written then.
    return self->pixels->empty() ? static_cast<void*>(self) : self->pixels->data();
  }
};

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

const char* kind_name(ImageKind kind) {
  return kind == ImageKind::Color ? "color images" : kind == ImageKind::Depth ? "depth images" : "normal images";
}

// One probe of the writer for path's extension, through a scratch file beside path.
const char* probe(const std::filesystem::path& path, int channels, tessref_image_io_type type, int& stored_float) {
  const std::filesystem::path folder = path.parent_path().empty() ? "." : path.parent_path();
  const std::filesystem::path scratch =
      folder / ("." + path.stem().string() + ".tessref-probe-" + std::to_string(::getpid()) + path.extension().string());
  return image_io().probe(scratch.c_str(), channels, type, &stored_float);
}

// The format of `kind` for path's extension, or the reason the writer cannot hold it.
struct ProbeAnswer {
  ImageFormat format;
  std::string error;  // empty: usable
};
ProbeAnswer ask_writer(const std::filesystem::path& path, ImageKind kind) {
  ProbeAnswer a;
  if (written_with_libpng(path))  // known without loading the module
    return kind == ImageKind::Color ? a : ProbeAnswer{{}, "it stores 8 or 16-bit integers, not floats"};
  int stored_float = 0;
  const int channels = kind == ImageKind::Depth ? 1 : 3;
  if (kind == ImageKind::Color) {
    // RGBA where the writer takes four channels, RGB where it takes three (.hdr), 8-bit RGB else.
    for (int n : {4, 3})
      if (!probe(path, n, TESSREF_IMAGE_IO_FLOAT, stored_float) && stored_float) return {{n, true}, ""};
    if (const char* e = probe(path, 3, TESSREF_IMAGE_IO_UINT8, stored_float)) a.error = e;
    return a;
  }
  if (const char* e = probe(path, channels, TESSREF_IMAGE_IO_FLOAT, stored_float)) a.error = e;
  else if (!stored_float) a.error = "it stores 8 or 16-bit integers, not floats";
  a.format = {channels, true};
  return a;
}

// Answers per (extension, kind): the probe runs once, in check_image_path, before any rendering.
std::mutex formats_mutex;
std::map<std::pair<std::string, ImageKind>, ProbeAnswer> known_formats;

const ProbeAnswer& answer_for(const std::filesystem::path& path, ImageKind kind) {
  std::lock_guard lock(formats_mutex);
  const auto key = std::make_pair(lower_extension(path), kind);
  auto it = known_formats.find(key);
  if (it == known_formats.end()) it = known_formats.emplace(key, ask_writer(path, kind)).first;
  return it->second;
}

std::uint8_t unorm8(float c) {
  if (!(c > 0.0f)) return 0;  // also NaN
  if (c >= 1.0f) return 255;
  return static_cast<std::uint8_t>(c * 255.0f + 0.5f);
}

}  // namespace

ImageFormat check_image_path(const std::filesystem::path& path, ImageKind kind) {
  const ProbeAnswer& a = answer_for(path, kind);
  if (a.error.empty()) return a.format;
  const std::string ext = lower_extension(path).empty() ? "(no extension)" : lower_extension(path);
  std::string need = kind_name(kind);
  if (kind == ImageKind::Depth) need += " (1 float channel)";
  if (kind == ImageKind::Normals) need += " (3 float channels)";
  throw InputError(path.string() + ": this build's OpenImageIO cannot write " + need + " as " + ext + ": " +
                   a.error + "; it can as " + writable_image_extensions(kind));
}

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

void write_color_image(const Framebuffer& fb, const std::filesystem::path& path, int draw_buffer) {
  if (draw_buffer != 0) {  // the same writer over that buffer's pixels
    Framebuffer view;
    view.width = fb.width;
    view.height = fb.height;
    view.color = *fb.draw_buffer(draw_buffer);
    view.depth = fb.depth;
    return write_color_image(view, path);
  }
  const ImageFormat format = check_image_path(path, ImageKind::Color);
  if (!format.stores_float) return write_rgb8_image(to_rgb8(fb), path);
  const int channels = format.channels;
  std::vector<float> rows = flipped(fb, channels, [&](std::size_t i, float* dst) {
    for (int k = 0; k < channels; ++k) dst[k] = fb.color[i][k];
  });
  write_image(path, fb.width, fb.height, channels, TESSREF_IMAGE_IO_FLOAT, rows.data());
}

void write_depth_image(const Framebuffer& fb, const std::filesystem::path& path) {
  check_image_path(path, ImageKind::Depth);
  std::vector<float> rows = flipped(fb, 1, [&](std::size_t i, float* dst) { dst[0] = fb.depth[i]; });
  write_image(path, fb.width, fb.height, 1, TESSREF_IMAGE_IO_FLOAT, rows.data(), {"Z"});
}

void write_normals_image(const Framebuffer& fb, const std::filesystem::path& path) {
  check_image_path(path, ImageKind::Normals);
  std::vector<float> rows = flipped(fb, 3, [&](std::size_t i, float* dst) {
    for (int k = 0; k < 3; ++k) dst[k] = fb.aux[i][k];
  });
  write_image(path, fb.width, fb.height, 3, TESSREF_IMAGE_IO_FLOAT, rows.data());
}

void write_float_channels(const std::filesystem::path& path, int width, int height,
                          const std::vector<std::string>& channel_names, const std::vector<float>& pixels) {
  std::vector<const char*> names;
  for (const std::string& n : channel_names) names.push_back(n.c_str());
  write_image(path, width, height, int(names.size()), TESSREF_IMAGE_IO_FLOAT, pixels.data(), names);
}

void write_rgb8_image(const Rgb8Image& image, const std::filesystem::path& path) {
  if (written_with_libpng(path)) return write_png_rgb8(path, image.width, image.height, image.pixels.data());
  write_image(path, image.width, image.height, 3, TESSREF_IMAGE_IO_UINT8, image.pixels.data());
  // Writers that keep floats (EXR, TIFF, HDR) report failed writes themselves; the 8-bit ones
  // (BMP, TGA, JPEG under a file-size limit or on a full disk, JPEG 2000 below 32 pixels)
  // may not, so their file counts as written only when it reads back whole.
  if (check_image_path(path, ImageKind::Color).stores_float) return;
  bool whole = false;
  try {
    const QuietStderr quiet;
    const Rgb8Image back = read_rgb8_image(path);  // 8 bits, as written: no float conversion
    whole = back.width == image.width && back.height == image.height;
  } catch (const InputError&) {
  }
  if (whole) return;
  // A full file system is the usual cause: name it when it is.
  std::error_code ec;
  const auto space = std::filesystem::space(std::filesystem::absolute(path).parent_path(), ec);
  if (!ec && space.available == 0)
    throw InputError(path.string() + ": the file system holding it is full (0 bytes free): the image was cut short");
  throw InputError(path.string() +
                   ": the written file does not read back whole (the writer failed without saying so: a full "
                   "disk, a file size limit, or an image size the format cannot hold)");
}

Rgb8Image read_rgb8_image(const std::filesystem::path& path) {
  Rgb8Image img;
  ReadTarget<std::uint8_t> target{&img.pixels};
  // Channels 0..2 as 8 bits (a gray image is read into the first channel only).
  check(image_io().read(path.string().c_str(), TESSREF_IMAGE_IO_UINT8, 3,
                        &ReadTarget<std::uint8_t>::alloc, &target));
  img.width = target.width;
  img.height = target.height;
  return img;
}

std::vector<std::string> read_channel_names(const std::filesystem::path& path) {
  const char* joined = nullptr;
  check(image_io().channel_names(path.string().c_str(), &joined));
  std::vector<std::string> names;
  for (const char* at = joined; *at;) {
    const char* end = std::strchr(at, '\n');
    names.emplace_back(at, end ? end : at + std::strlen(at));
    if (!end) break;
    at = end + 1;
  }
  return names;
}

FloatImage read_float_image(const std::filesystem::path& path) {
  FloatImage img;
  ReadTarget<float> target{&img.pixels};
  check(image_io().read(path.string().c_str(), TESSREF_IMAGE_IO_FLOAT, 0, &ReadTarget<float>::alloc,
                        &target));
  img.width = target.width;
  img.height = target.height;
  img.channels = target.channels;
  int is_float = 1;
  check(image_io().stored_format(path.string().c_str(), &img.stored_bits, &is_float));
  img.stored_float = is_float != 0;
  return img;
}

std::string writable_image_extensions(ImageKind kind) {
  std::string all = image_io().writable_extensions(), out;
  for (std::size_t a = 0, b; a < all.size(); a = b + 1) {
    b = std::min(all.find(' ', a), all.size());
    const std::string ext = all.substr(a, b - a);
    // Only the common image files: OpenImageIO also lists pseudo-formats (.null, .term).
    static const char* const kFiles[] = {".exr", ".tif", ".tiff", ".hdr", ".pfm", ".png", ".jpg", ".jpeg",
                                         ".bmp", ".tga", ".webp", ".dpx", ".sgi", ".rla", ".fits", ".ppm",
                                         ".pgm", ".jp2", ".gif", ".ico", ".heic", ".cin"};
    if (std::find_if(std::begin(kFiles), std::end(kFiles), [&](const char* f) { return ext == f; }) == std::end(kFiles))
      continue;
    // Listed is not writable: Debian's OpenImageIO 2.4 lists .pfm but has no writer for it.
    if (!answer_for(std::filesystem::temp_directory_path() / ("x" + ext), kind).error.empty()) continue;
    out += (out.empty() ? "" : " ") + ext;
  }
  return out;
}

ImageFileDiff diff_image_files(const std::filesystem::path& a, const std::filesystem::path& b,
                               double warn_threshold, double fail_threshold,
                               const std::filesystem::path& diff_path, double diff_scale) {
  tessref_image_io_diff d{};
  check(image_io().diff(a.c_str(), b.c_str(), warn_threshold, fail_threshold,
                        diff_path.empty() ? nullptr : diff_path.c_str(), diff_scale, &d));
  return ImageFileDiff{d.width, d.height, d.channels, d.mean_error, d.rms_error, d.psnr, d.max_error,
                       d.max_x, d.max_y, d.max_c, d.over_warn, d.over_fail};
}

std::string image_io_module_path() { return loaded_module().path; }

}  // namespace tessref
