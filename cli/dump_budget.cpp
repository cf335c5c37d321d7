#include "cli/dump_budget.h"

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

}  // namespace

DumpBudget::DumpBudget(const std::string& dump_path, std::uint64_t max_dump_bytes)
    : path_(dump_path), max_dump_bytes_(max_dump_bytes) {
  std::error_code ec;
  const std::filesystem::path folder = std::filesystem::absolute(dump_path).parent_path();
  const std::filesystem::space_info space = std::filesystem::space(folder, ec);
  if (!ec) {
    const std::uint64_t margin = 64ull << 20;
    limit_ = space.available > margin ? space.available - margin : 0;
    bound_ = "the " + gigabytes(limit_) + " free in " + folder.string() + " (less 64 MiB for the images)";
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
