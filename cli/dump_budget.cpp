#include "cli/dump_budget.h"

#include <sys/stat.h>

#include <cstdio>
#include <filesystem>

#include "common/error.h"

namespace tessref::cli {
namespace {

std::string gigabytes(std::uint64_t bytes) {
  char buf[64];
  const double b = double(bytes);
  const unsigned long long n = bytes;
  if (b >= 1e9) std::snprintf(buf, sizeof buf, "%.1f GB (%llu bytes)", b / 1e9, n);
  else if (b >= 1e6) std::snprintf(buf, sizeof buf, "%.1f MB (%llu bytes)", b / 1e6, n);
  else std::snprintf(buf, sizeof buf, "%llu bytes", n);
  return buf;
}

// The file system a file will be written to (its folder's device); -1 if the folder is not there.
long long device_of(const std::string& path) {
  struct stat st {};
  const std::filesystem::path folder = std::filesystem::absolute(path).parent_path();
  return ::stat(folder.c_str(), &st) == 0 ? (long long)st.st_dev : -1;
}

}  // namespace

DumpBudget::DumpBudget(const std::string& dump_path, std::uint64_t max_dump_bytes,
                       const std::vector<std::string>& image_paths, std::uint64_t image_bytes)
    : path_(dump_path), max_dump_bytes_(max_dump_bytes) {
  std::error_code ec;
  const std::filesystem::path folder = std::filesystem::absolute(dump_path).parent_path();
  const std::filesystem::space_info space = std::filesystem::space(folder, ec);
  if (!ec) {
    // Room for the images written to the same file system only: a dump alone on a small one may
    // use all of it.
    const long long device = device_of(dump_path);
    std::uint64_t margin = 0;
    int images = 0;
    for (const std::string& image : image_paths)
      if (device_of(image) == device) margin += image_bytes, ++images;
    limit_ = space.available > margin ? space.available - margin : 0;
    bound_ = "the " + gigabytes(limit_) + " free in " + folder.string();
    if (images)
      bound_ += " (less " + gigabytes(margin) + " for the " + std::to_string(images) + " image" + (images > 1 ? "s" : "") +
                " written there)";
  }
  if (max_dump_bytes != 0 && max_dump_bytes < limit_) {
    limit_ = max_dump_bytes;
    bound_ = "--max-dump-bytes " + std::to_string(max_dump_bytes);
  }
}

void DumpBudget::check_estimate(std::uint64_t tes_invocations, bool text) const {
  const std::uint64_t estimate = TessDumpWriter::estimated_bytes(tes_invocations, text);
  if (estimate > limit_)
    throw InputError(path_ + ": --dump-tess would write " + (text ? "about " : "") + gigabytes(estimate) + " (" +
                     std::to_string(tes_invocations) + " tessellated vertices), more than " + bound_ +
                     "; lower the levels or dump to another place" +
                     (max_dump_bytes_ == limit_ ? ", or raise --max-dump-bytes" : ""));
}

void DumpBudget::check_written(const TessDumpWriter& dump) const {
  if (dump.bytes_written() > limit_)
    throw InputError(path_ + ": --dump-tess stopped after " + gigabytes(dump.bytes_written()) + " (" +
                     std::to_string(dump.records_written()) + " tessellated vertices), more than " + bound_ +
                     "; nothing was written");
}

}  // namespace tessref::cli
