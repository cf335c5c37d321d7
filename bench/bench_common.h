#pragma once
// What the benchmarks share: one GL context for the process (the llvmpipe baselines skip where
// none can be made) and a main that prints each benchmark's ratio table after the runs.
#include <benchmark/benchmark.h>

#include <map>
#include <string>
#include <vector>

#ifdef TESSREF_HAVE_GLREF
#include <cstdio>
#include <memory>

#include "glref/gl_context.h"
#include "glref/malloc_tuning.h"
#endif

namespace tessref::bench {

#ifdef TESSREF_HAVE_GLREF
inline glref::GlContext* gl_context() {
  static std::unique_ptr<glref::GlContext> ctx = [] {
    try {
      return std::make_unique<glref::GlContext>();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "llvmpipe baseline unavailable: %s\n", e.what());
      return std::unique_ptr<glref::GlContext>();
    }
  }();
  return ctx.get();
}
#endif

// Prints as the console reporter does and keeps one rate counter of every successful run, by
// benchmark name, for the ratio table a benchmark prints at the end.
class RateReporter : public benchmark::ConsoleReporter {
 public:
  explicit RateReporter(std::string counter) : counter_(std::move(counter)) {}
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      if (r.error_occurred) continue;
      const auto it = r.counters.find(counter_);
      if (it != r.counters.end()) rates_[r.benchmark_name()] = it->second.value;
    }
  }
  // The counter of benchmark `name` ("BM_X/64"), 0 if it did not run.
  double rate(const std::string& name) const {
    const auto it = rates_.find(name);
    return it == rates_.end() ? 0.0 : it->second;
  }

 private:
  std::string counter_;
  std::map<std::string, double> rates_;
};

// Reporter: a benchmark::ConsoleReporter with print_ratios(), called after all runs.
template <typename Reporter>
int run_benchmarks(int argc, char** argv) {
#ifdef TESSREF_HAVE_GLREF
  glref::keep_draw_buffers_off_mmap();  // before anything allocates
#endif
  benchmark::Initialize(&argc, argv);
  Reporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.print_ratios();
  benchmark::Shutdown();
  return 0;
}

}  // namespace tessref::bench
