// Domain points generated per second by tessref's primitive generator at levels 8, 16 and 64,
// beside Mesa llvmpipe generating the same patches (transform feedback capture of gl_TessCoord
// with rasterizer discard), measured in the same process (wall time). The closing table gives the
// ratios.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <memory>
#include <string>

#include "stages/tpg.h"
#include "bench_common.h"
#ifdef TESSREF_HAVE_GLREF
#include "glref/gl_context.h"
#include "glref/tess_capture.h"
#endif

namespace {

using namespace tessref;

constexpr TessLayout kLayout{TessDomain::Triangles, TessSpacing::FractionalOdd, TessWinding::Ccw,
                             false};

TessLevels uniform_levels(float level) {
  TessLevels l;
  l.outer = {level, level, level, level};
  l.inner = {level, level};
  return l;
}

void BM_TessrefTpg(benchmark::State& state) {
  const TessLevels levels = uniform_levels(float(state.range(0)));
  TessDomainPoints out;
  std::size_t points = 0;
  for (auto _ : state) {
    generate_tessellation(kLayout, levels, TessProfile::llvmpipe(), out);
    benchmark::DoNotOptimize(out.coords.data());
    points += out.coords.size();
  }
  bench::set_work_counters(state, bench::work::tpg(out.coords.size(), out.primitive_count()));
  state.counters["points_per_s"] = benchmark::Counter(double(points), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_TessrefTpg)->Arg(8)->Arg(16)->Arg(64)->Unit(benchmark::kMicrosecond)->UseRealTime();

#ifdef TESSREF_HAVE_GLREF

void BM_LlvmpipeTpg(benchmark::State& state) {
  glref::GlContext* ctx = bench::gl_context();
  if (!ctx) {
    state.SkipWithError("no GL context");
    return;
  }
  const TessLevels levels = uniform_levels(float(state.range(0)));
  // One draw's worth of patches (kept under the 65,535-vertex chunk limit by TessCapture).
  const std::size_t per_patch = generate_tessellation(kLayout, levels).coords.size();
  const std::vector<TessLevels> batch(std::max<std::size_t>(1, 50000 / per_patch), levels);
  glref::TessCapture capture(*ctx);
  std::size_t points = 0;
  for (auto _ : state) {
    auto result = capture.capture(kLayout, batch);
    benchmark::DoNotOptimize(result.data());
    points += batch.size() * per_patch;
  }
  const std::size_t per_patch_triangles = generate_tessellation(kLayout, levels).primitive_count();
  bench::set_work_counters(state, bench::work::tpg(batch.size() * per_patch, batch.size() * per_patch_triangles));
  state.counters["points_per_s"] = benchmark::Counter(double(points), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_LlvmpipeTpg)->Arg(8)->Arg(16)->Arg(64)->Unit(benchmark::kMillisecond)->UseRealTime();
#endif

// Collects points_per_s per (implementation, level) to print the ratios at the end.
class RatioReporter : public bench::RateReporter {
 public:
  RatioReporter() : RateReporter("points_per_s") {}
  void print_ratios() const {
    std::printf("\nlevel  tessref Mpoints/s  llvmpipe Mpoints/s  ratio\n");
    for (int level : {8, 16, 64}) {
      const double t = rate("BM_TessrefTpg/" + std::to_string(level) + "/real_time");
      const double l = rate("BM_LlvmpipeTpg/" + std::to_string(level) + "/real_time");
      if (t == 0.0) continue;
      if (l == 0.0) {
        std::printf("%5d  %17.1f  %18s  %5s\n", level, t / 1e6, "n/a", "n/a");
        continue;
      }
      std::printf("%5d  %17.1f  %18.1f  %5.1fx\n", level, t / 1e6, l / 1e6, t / l);
    }
  }
};

}  // namespace

int main(int argc, char** argv) { return tessref::bench::run_benchmarks<RatioReporter>(argc, argv); }
