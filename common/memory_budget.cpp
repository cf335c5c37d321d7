#include "common/memory_budget.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>

#if defined(__SANITIZE_ADDRESS__)
#define TESSREF_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TESSREF_ASAN 1
#endif
#endif

namespace tessref {
namespace {

std::uint64_t g_budget = 0;

// A cgroup's memory limit: cgroup v2's memory.max ("max" for none), else v1's limit_in_bytes
// (a huge number for none). 0 where neither holds a limit.
std::uint64_t cgroup_limit() {
  for (const char* path : {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"}) {
    std::ifstream in(path);
    unsigned long long value = 0;
    if (in >> value && value > 0 && value < (1ull << 62)) return value;
  }
  return 0;
}

}  // namespace

std::uint64_t machine_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  std::uint64_t physical = pages > 0 && page > 0 ? std::uint64_t(pages) * std::uint64_t(page) : 0;
  const std::uint64_t cgroup = cgroup_limit();
  if (physical == 0) return cgroup;
  return cgroup ? std::min(physical, cgroup) : physical;
}

std::uint64_t default_memory_budget() {
  const std::uint64_t three_quarters = machine_memory_bytes() / 4 * 3;
  return three_quarters < kMinMemoryBudget ? 0 : three_quarters;  // a tiny machine: no bound
}

bool set_memory_budget(std::uint64_t bytes) {
#ifdef TESSREF_ASAN
  (void)bytes;
  return false;
#else
  rlimit limit{};
  if (getrlimit(RLIMIT_DATA, &limit) != 0) return false;
  const rlim_t wanted = bytes == 0 ? limit.rlim_max : rlim_t(std::min<std::uint64_t>(bytes, limit.rlim_max));
  limit.rlim_cur = wanted;
  if (setrlimit(RLIMIT_DATA, &limit) != 0) return false;
  g_budget = bytes == 0 ? 0 : std::uint64_t(wanted);
  return true;
#endif
}

std::uint64_t memory_budget() { return g_budget; }

std::string format_bytes(std::uint64_t bytes) {
  static const char* units[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  if (bytes < 1024) return std::to_string(bytes) + (bytes == 1 ? " byte" : " bytes");
  double value = double(bytes) / 1024.0;
  int unit = 0;
  while (value >= 1024.0 && unit < 5) {
    value /= 1024.0;
    ++unit;
  }
  char text[32];
  std::snprintf(text, sizeof text, "%.1f %s", value, units[unit]);
  return text;
}

}  // namespace tessref
