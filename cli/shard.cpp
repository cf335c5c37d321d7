#include "cli/shard.h"

#include <algorithm>
#include <cstdlib>

#include "common/error.h"

namespace tessref::cli {
namespace {

// A whole non-negative decimal number, or -1.
long long whole_number(const std::string& s) {
  if (s.empty() || s.size() > 9 || !std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return -1;
  return std::stoll(s);
}

long long env_number(const char* name) {
  const char* v = std::getenv(name);
  return v ? whole_number(v) : -2;  // -2: unset, -1: not a number
}

}  // namespace

Shard parse_shard(const std::string& text, const std::string& option) {
  const std::string usage = option + " '" + text + "': expected I/N with 0 <= I < N (0-based, as SLURM_ARRAY_TASK_ID), " +
                            "'auto' or 'auto/N'";
  const std::size_t slash = text.find('/');
  const std::string first = text.substr(0, slash);
  const std::string second = slash == std::string::npos ? "" : text.substr(slash + 1);
  long long index = -1, count = -1;
  if (first == "auto") {
    if (slash != std::string::npos && (count = whole_number(second)) < 1) throw InputError(usage);
    const char* source = "SLURM_ARRAY_TASK_ID";
    index = env_number(source);
    if (index >= 0) {
      // A job array may start at 1 (--array=1-4); the shard index counts from its first task.
      const long long min = env_number("SLURM_ARRAY_TASK_MIN");
      if (min > 0) index -= min;
      if (count < 0) count = env_number("SLURM_ARRAY_TASK_COUNT");
    } else {
      source = "JOB_COMPLETION_INDEX";
      index = env_number(source);
      if (count < 0) count = env_number("TESSREF_SHARD_COUNT");
    }
    if (index == -2)
      throw InputError(option + " auto: neither SLURM_ARRAY_TASK_ID (Slurm job array) nor JOB_COMPLETION_INDEX "
                                "(Kubernetes Indexed Job) is set");
    if (index < 0) throw InputError(option + " auto: " + source + " is not a whole number");
    if (count < 1)
      throw InputError(option + " auto: the shard count is unknown or not a positive number (give auto/N, or set "
                                "SLURM_ARRAY_TASK_COUNT or TESSREF_SHARD_COUNT)");
    if (index >= count)
      throw InputError(option + " auto: " + source + " gives shard " + std::to_string(index) + ", not below the count " +
                       std::to_string(count));
    return Shard{int(index), int(count)};
  }
  if (slash == std::string::npos) throw InputError(usage);
  index = whole_number(first);
  count = whole_number(second);
  if (index < 0 || count < 1 || index >= count) throw InputError(usage);
  return Shard{int(index), int(count)};
}

std::vector<CampaignScene> campaign_scenes(const std::filesystem::path& folder, const Shard& shard) {
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().extension() == ".json" && it->is_regular_file()) files.push_back(it->path());
  if (ec) throw InputError(folder.string() + ": cannot list the scene folder: " + ec.message());
  if (files.empty()) throw InputError(folder.string() + ": the scene folder holds no *.json scene");
  std::sort(files.begin(), files.end(),
            [](const auto& a, const auto& b) { return a.filename().string() < b.filename().string(); });
  std::vector<CampaignScene> out;
  for (std::size_t i = 0; i < files.size(); ++i)
    if (shard.holds(i)) out.push_back({i, files[i].stem().string(), files[i]});
  return out;
}

}  // namespace tessref::cli
