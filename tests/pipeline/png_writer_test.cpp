// io/png_writer.h: PNG files written with libpng directly must hold the bytes the image I/O
// module (OpenImageIO's PNG writer) wrote before, so that every output hash stays the same.
#include <dlfcn.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/error.h"
#include "io/image_io_module.h"
#include "io/image_output.h"
#include "io/png_writer.h"
#include "test_util.h"

namespace tessref {
namespace {

using test::TempDir;

std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// The module of this build tree, opened as image_output.cpp opens it.
const tessref_image_io_api* module_api() {
  static const tessref_image_io_api* api = [] {
    void* handle = ::dlopen(TESSREF_IMAGE_IO_MODULE_PATH, RTLD_NOW | RTLD_LOCAL);
    if (!handle) return static_cast<const tessref_image_io_api*>(nullptr);
    auto entry = reinterpret_cast<tessref_image_io_entry_fn>(::dlsym(handle, TESSREF_IMAGE_IO_ENTRY));
    return entry ? entry() : nullptr;
  }();
  return api;
}

// Pixels of three kinds: noise (filters and deflate see no structure), a smooth gradient (the
// adaptive filter picks Sub, Up, Average and Paeth rows) and flat colour (long matches).
std::vector<std::uint8_t> pattern(int width, int height, int kind, std::uint32_t seed) {
  std::vector<std::uint8_t> p(std::size_t(width) * height * 3);
  std::mt19937 rng(seed);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::size_t pixel = i / 3, x = pixel % width, y = pixel / width;
    p[i] = kind == 0   ? std::uint8_t(rng())
           : kind == 1 ? std::uint8_t((x * 255 / std::max(1, width - 1) + y * (i % 3 + 1)) & 0xff)
                       : std::uint8_t(i % 3 == 0 ? 200 : 51);
  }
  return p;
}

TEST(PngWriter, GivesTheModulesBytes) {
  const tessref_image_io_api* api = module_api();
  ASSERT_NE(api, nullptr) << "the image I/O module of this build is not loadable: " << ::dlerror();
  TempDir dir;
  const struct { int width, height; } sizes[] = {{1, 1}, {17, 5}, {300, 200}, {1024, 96}, {2731, 3}};
  int compared = 0;
  for (const auto& size : sizes)
    for (int kind = 0; kind < 3; ++kind) {
      const std::vector<std::uint8_t> pixels = pattern(size.width, size.height, kind, std::uint32_t(compared + 1));
      const std::filesystem::path ours = dir.path() / "ours.png", theirs = dir.path() / "theirs.png";
      write_png_rgb8(ours, size.width, size.height, pixels.data());
      ASSERT_EQ(api->write(theirs.c_str(), size.width, size.height, 3, TESSREF_IMAGE_IO_UINT8, pixels.data(),
                           nullptr),
                nullptr);
      const std::string a = file_bytes(ours), b = file_bytes(theirs);
      ASSERT_GT(a.size(), 8u);
      EXPECT_TRUE(a == b) << size.width << "x" << size.height << " pattern " << kind << ": " << a.size()
                          << " bytes against the module's " << b.size();
      ++compared;
    }
  EXPECT_EQ(compared, 15);
}

TEST(PngWriter, ReadsBackAsWritten) {
  TempDir dir;
  const std::vector<std::uint8_t> pixels = pattern(33, 7, 0, 7);
  const std::filesystem::path path = dir.path() / "x.PNG";  // the extension in any case
  write_rgb8_image(Rgb8Image{33, 7, pixels}, path);
  const Rgb8Image back = read_rgb8_image(path);
  EXPECT_EQ(back.width, 33);
  EXPECT_EQ(back.height, 7);
  EXPECT_TRUE(back.pixels == pixels);
}

TEST(PngWriter, AnUnwritablePathIsAnInputErrorNamingIt) {
  TempDir dir;
  const std::filesystem::path path = dir.path() / "no-such-folder" / "x.png";
  const std::vector<std::uint8_t> pixels(12, 0);
  try {
    write_png_rgb8(path, 2, 2, pixels.data());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path.string() + ": cannot open for writing: No such file or directory");
  }
  EXPECT_THROW(write_png_rgb8(dir.path() / "empty.png", 0, 4, pixels.data()), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "empty.png"));
}

// /dev/full takes the open and fails every write with ENOSPC: the error says so and the
// writer leaves nothing behind (here: it cannot remove a device, and must not try harder).
TEST(PngWriter, AFailedWriteIsNamed) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  const std::vector<std::uint8_t> pixels = pattern(64, 64, 0, 3);
  try {
    write_png_rgb8("/dev/full", 64, 64, pixels.data());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/full: the file system holding it is full"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace tessref
