// The machine's limits, for the "share of the limit" figures of scripts/bench.sh:
//   copy:        memcpy between two arrays much larger than the caches, every thread its own pair
//                (bytes read + bytes written, as STREAM counts them, no write-allocate traffic);
//   write:       memset of such an array (bytes written);
//   cache write: memset of a 256 KiB buffer per thread, over and over (stays in L2);
//   fma:         fp32 fused multiply-adds, 12 independent 8-wide accumulator chains per thread
//                (AVX2 + FMA when the CPU has them, checked at run time; else 4-wide SSE mul + add).
// Each on 1 thread and on all hardware threads; best of several trials (as STREAM reports).
//
//   machine_limits [--quick] [--json FILE]
//
// Plain C++ (std::thread), built with the project's flags and no -march=native.
#include <immintrin.h>

#include <algorithm>
#include <barrier>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

// Runs work(thread) on `threads` threads at once, `trials` times; returns the best wall time of a
// trial in seconds. setup(thread) runs once per thread before the first trial (first touch).
double best_time(int threads, int trials, const std::function<void(int)>& setup,
                 const std::function<void(int)>& work) {
  std::barrier sync(threads + 1);
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t)
    pool.emplace_back([&, t] {
      setup(t);
      sync.arrive_and_wait();  // set up
      for (int i = 0; i < trials; ++i) {
        sync.arrive_and_wait();  // start
        work(t);
        sync.arrive_and_wait();  // done
      }
    });
  sync.arrive_and_wait();
  double best = 1e30;
  for (int i = 0; i < trials; ++i) {
    sync.arrive_and_wait();
    const auto t0 = Clock::now();
    sync.arrive_and_wait();
    best = std::min(best, std::chrono::duration<double>(Clock::now() - t0).count());
  }
  for (auto& th : pool) th.join();
  return best;
}

struct Buffers {
  std::vector<std::unique_ptr<char[]>> a, b;
  explicit Buffers(int threads) : a(threads), b(threads) {}
};

// GB/s of memcpy (2 x bytes per element moved) or memset (1 x) over `bytes` per thread.
double copy_gbs(int threads, std::size_t bytes, int repeats, int trials) {
  Buffers buf(threads);
  const double s = best_time(
      threads, trials,
      [&](int t) {
        buf.a[t].reset(new char[bytes]);
        buf.b[t].reset(new char[bytes]);
        std::memset(buf.a[t].get(), 1, bytes);
        std::memset(buf.b[t].get(), 2, bytes);
      },
      [&](int t) {
        for (int r = 0; r < repeats; ++r) {
          std::memcpy(buf.a[t].get(), buf.b[t].get(), bytes);
          asm volatile("" : : "r"(buf.a[t].get()) : "memory");  // keep every pass
        }
      });
  return 2.0 * double(bytes) * repeats * threads / s / 1e9;
}

double write_gbs(int threads, std::size_t bytes, int repeats, int trials) {
  Buffers buf(threads);
  const double s = best_time(
      threads, trials,
      [&](int t) {
        buf.a[t].reset(new char[bytes]);
        std::memset(buf.a[t].get(), 1, bytes);
      },
      [&](int t) {
        for (int r = 0; r < repeats; ++r) {
          std::memset(buf.a[t].get(), r & 0xff, bytes);
          asm volatile("" : : "r"(buf.a[t].get()) : "memory");  // keep every pass
        }
      });
  return double(bytes) * repeats * threads / s / 1e9;
}

constexpr int kChains = 12;  // FMA latency (4-5 cycles) x 2 FMA pipes, with margin

__attribute__((target("avx2,fma"))) float fma_avx2(std::uint64_t iterations) {
  __m256 acc[kChains];
  for (int k = 0; k < kChains; ++k) acc[k] = _mm256_set1_ps(float(k) * 0.01f);
  const __m256 m = _mm256_set1_ps(0.999999f), c = _mm256_set1_ps(1e-6f);
  for (std::uint64_t i = 0; i < iterations; ++i)
    for (int k = 0; k < kChains; ++k) acc[k] = _mm256_fmadd_ps(acc[k], m, c);
  __m256 s = acc[0];
  for (int k = 1; k < kChains; ++k) s = _mm256_add_ps(s, acc[k]);
  alignas(32) float out[8];
  _mm256_store_ps(out, s);
  return out[0] + out[7];
}

// Fallback: SSE (x86-64 baseline), separate multiply and add.
float muladd_sse(std::uint64_t iterations) {
  __m128 acc[kChains];
  for (int k = 0; k < kChains; ++k) acc[k] = _mm_set1_ps(float(k) * 0.01f);
  const __m128 m = _mm_set1_ps(0.999999f), c = _mm_set1_ps(1e-6f);
  for (std::uint64_t i = 0; i < iterations; ++i)
    for (int k = 0; k < kChains; ++k) acc[k] = _mm_add_ps(_mm_mul_ps(acc[k], m), c);
  __m128 s = acc[0];
  for (int k = 1; k < kChains; ++k) s = _mm_add_ps(s, acc[k]);
  return _mm_cvtss_f32(s);
}

bool have_fma() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}

double fma_gflops(int threads, std::uint64_t iterations, int trials) {
  const bool fma = have_fma();
  std::vector<float> sink(threads);
  const double s = best_time(
      threads, trials, [](int) {},
      [&](int t) { sink[t] = fma ? fma_avx2(iterations) : muladd_sse(iterations); });
  volatile float keep = sink[0];
  (void)keep;
  // Per iteration and chain: 8 lanes x 2 flops (FMA), or 4 lanes x 2 flops (mul + add).
  const double flops = double(iterations) * kChains * (fma ? 16.0 : 8.0) * threads;
  return flops / s / 1e9;
}

struct Limits {
  int threads = 1;
  double copy[2]{}, write[2]{}, cache_write[2]{}, fma[2]{};  // [0] one thread, [1] all threads
};

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  const char* json = nullptr;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick")) quick = true;
    else if (!std::strcmp(argv[i], "--json") && i + 1 < argc) json = argv[++i];
    else {
      std::fprintf(stderr, "usage: machine_limits [--quick] [--json FILE]\n");
      return 2;
    }
  }
  Limits l;
  l.threads = int(std::max(1u, std::thread::hardware_concurrency()));
  const std::size_t big = std::size_t(quick ? 64 : 128) << 20;  // per array, per thread
  const int trials = quick ? 3 : 7;
  const std::uint64_t fma_iterations = quick ? 20000000 : 50000000;  // ~0.1-0.3 s per trial
  for (int which = 0; which < 2; ++which) {
    const int threads = which == 0 ? 1 : l.threads;
    l.copy[which] = copy_gbs(threads, big, 2, trials);
    l.write[which] = write_gbs(threads, big, 2, trials);
    l.cache_write[which] = write_gbs(threads, 256 << 10, 4000, trials);
    l.fma[which] = fma_gflops(threads, fma_iterations, trials);
  }
  // All threads can do at least what one does: a lower all-thread figure means the other cores
  // were busy (a shared machine); the one-thread figure is then the better bound.
  bool disturbed = false;
  for (double* v : {l.copy, l.write, l.cache_write, l.fma})
    if (v[1] < v[0]) {
      v[1] = v[0];
      disturbed = true;
    }
  const char* kind = have_fma() ? "avx2+fma, 8-wide" : "sse mul+add, 4-wide";
  std::printf("machine limits (%d hardware threads; %zu MiB arrays per thread; best of %d)\n",
              l.threads, big >> 20, trials);
  std::printf("%-32s %12s %12s\n", "", "1 thread", "all threads");
  std::printf("%-32s %12.1f %12.1f\n", "copy GB/s (read + write)", l.copy[0], l.copy[1]);
  std::printf("%-32s %12.1f %12.1f\n", "write GB/s", l.write[0], l.write[1]);
  std::printf("%-32s %12.1f %12.1f\n", "cache write GB/s (256 KiB)", l.cache_write[0], l.cache_write[1]);
  std::printf("%-32s %12.1f %12.1f\n", ("fp32 GFLOP/s (" + std::string(kind) + ")").c_str(), l.fma[0], l.fma[1]);
  if (disturbed)
    std::printf("(some all-thread figures came out below one thread's, other work sharing the cores;\n"
                " the one-thread figure is given for them)\n");
  if (json) {
    FILE* f = std::fopen(json, "w");
    if (!f) {
      std::fprintf(stderr, "machine_limits: cannot write %s\n", json);
      return 2;
    }
    std::fprintf(f,
                 "{\n  \"threads\": %d,\n  \"array_mib\": %zu,\n  \"fma_kind\": \"%s\",\n"
                 "  \"copy_gbs\": [%.3f, %.3f],\n  \"write_gbs\": [%.3f, %.3f],\n"
                 "  \"cache_write_gbs\": [%.3f, %.3f],\n  \"fma_gflops\": [%.3f, %.3f],\n"
                 "  \"all_threads_disturbed\": %s\n}\n",
                 l.threads, big >> 20, kind, l.copy[0], l.copy[1], l.write[0], l.write[1],
                 l.cache_write[0], l.cache_write[1], l.fma[0], l.fma[1], disturbed ? "true" : "false");
    std::fclose(f);
  }
  return 0;
}
