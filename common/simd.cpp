#include "common/simd.h"

#include <atomic>
#include <cstdlib>
#include <cstring>

namespace tessref {
namespace {

SimdPath initial_path() {
  const char* env = std::getenv("TESSREF_SIMD");
  if (env && std::strcmp(env, "scalar") == 0) return SimdPath::Scalar;
  return cpu_has_avx2() ? SimdPath::Avx2 : SimdPath::Scalar;
}

std::atomic<SimdPath>& current() {
  static std::atomic<SimdPath> path{initial_path()};
  return path;
}

}  // namespace

bool cpu_has_avx2() {
#if defined(__x86_64__) || defined(__i386__)
  return __builtin_cpu_supports("avx2");
#else
  return false;
#endif
}

SimdPath simd_path() { return current().load(std::memory_order_relaxed); }

void set_simd_path(SimdPath path) {
  if (path == SimdPath::Avx2 && !cpu_has_avx2()) path = SimdPath::Scalar;
  current().store(path, std::memory_order_relaxed);
}

const char* to_string(SimdPath path) { return path == SimdPath::Avx2 ? "avx2" : "scalar"; }

}  // namespace tessref
