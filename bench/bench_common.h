#pragma once
// What the benchmarks share: one GL context for the process (the llvmpipe baselines skip where
// none can be made) and a main that prints each benchmark's ratio table after the runs.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <map>
#include <set>
#include <string>
#include <vector>

#include "work_model.h"

#ifdef TESSREF_HAVE_GLREF
#include <cstdio>
#include <memory>

#include "glref/gl_context.h"
#include "common/malloc_tuning.h"
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

// A benchmark's per-iteration work (work_model.h) as counters, read by bench_report:
// model_items, model_bytes, model_flops.
inline void set_work_counters(benchmark::State& state, const work::Work& w) {
  state.counters["model_items"] = w.items;
  state.counters["model_bytes"] = w.bytes;
  state.counters["model_flops"] = w.flops;
}

// Prints as the console reporter does and keeps, by run name ("BM_X/64", "BM_Y/12/real_time"),
// the real time per iteration and the counters of each successful run: with
// --benchmark_repetitions the median aggregate (frame times here are bimodal under load), else
// the last iteration run.
class MedianReporter : public benchmark::ConsoleReporter {
 public:
  // Colors only on a terminal (--benchmark_color applies to the library's own reporter only).
  MedianReporter() : ConsoleReporter(isatty(STDOUT_FILENO) ? OO_ColorTabular : OO_Tabular) {}
  struct Result {
    double real_seconds = 0.0;  // per iteration
    std::map<std::string, double> counters;
  };
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      if (r.error_occurred) continue;
      const bool median = r.run_type == Run::RT_Aggregate && r.aggregate_name == "median";
      if (r.run_type != Run::RT_Iteration && !median) continue;
      const std::string key = r.run_name.str();
      if (!median && medians_.count(key)) continue;
      if (median) medians_.insert(key);
      Result& out = results_[key];
      out.real_seconds = r.GetAdjustedRealTime() / benchmark::GetTimeUnitMultiplier(r.time_unit);
      out.counters.clear();
      for (const auto& [name, c] : r.counters) out.counters[name] = c.value;
    }
  }
  // The result of run `name`, nullptr if it did not run (or failed).
  const Result* result(const std::string& name) const {
    const auto it = results_.find(name);
    return it == results_.end() ? nullptr : &it->second;
  }

 private:
  std::map<std::string, Result> results_;
  std::set<std::string> medians_;
};

// A MedianReporter read through one rate counter, for the ratio table a benchmark prints at the end.
class RateReporter : public MedianReporter {
 public:
  explicit RateReporter(std::string counter) : counter_(std::move(counter)) {}
  // The counter of benchmark `name` ("BM_X/64"), 0 if it did not run.
  double rate(const std::string& name) const {
    const Result* r = result(name);
    if (!r) return 0.0;
    const auto it = r->counters.find(counter_);
    return it == r->counters.end() ? 0.0 : it->second;
  }

 private:
  std::string counter_;
};

// Reporter: a benchmark::ConsoleReporter with print_ratios(), called after all runs.
template <typename Reporter>
int run_benchmarks(int argc, char** argv) {
#ifdef TESSREF_HAVE_GLREF
  keep_draw_buffers_off_mmap();  // before anything allocates
#endif
  benchmark::Initialize(&argc, argv);
  Reporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.print_ratios();
  benchmark::Shutdown();
  return 0;
}

}  // namespace tessref::bench
