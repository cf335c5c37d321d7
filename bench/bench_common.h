#pragma once
// What the benchmarks share: one GL context for the process (the llvmpipe baselines skip where
// none can be made) and a main that prints each benchmark's ratio table after the runs.
#include <benchmark/benchmark.h>

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
