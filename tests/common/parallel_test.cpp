// tessref::Parallel::for_each, the one entry point to TBB (common/parallel.h): every index runs
// once on any thread count, the work before it is seen by every call and every call's work after
// it, and a failure rethrows the exception of the lowest failed index. Also run under
// ThreadSanitizer by scripts/sanitize.sh tsan, with the happens-before annotations of
// common/parallel.cpp.
#include <gtest/gtest.h>

#include <atomic>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/parallel.h"

namespace tessref {
namespace {

TEST(Parallel, EveryIndexRunsOnceOnAnyThreadCount) {
  for (int threads : {1, 2, 3, 8}) {
    const Parallel parallel(threads);
    for (std::size_t n : {0, 1, 2, 7, 1000}) {
      SCOPED_TRACE(std::to_string(threads) + " threads, n = " + std::to_string(n));
      const auto runs = std::make_unique<std::atomic<int>[]>(n);
      for (std::size_t i = 0; i < n; ++i) runs[i] = 0;
      parallel.for_each(n, [&](std::size_t i) { ++runs[i]; });
      for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(runs[i], 1) << "index " << i;
    }
  }
}

TEST(Parallel, CallsSeeTheWorkBeforeAndTheCallerSeesTheirWorkAfter) {
  for (int threads : {2, 8}) {
    const Parallel parallel(threads);
    std::vector<int> in(5000), out(in.size(), -1);
    for (std::size_t i = 0; i < in.size(); ++i) in[i] = int(i) * 3;  // plain writes before
    parallel.for_each(in.size(), [&](std::size_t i) { out[i] = in[i] + 1; });
    for (std::size_t i = 0; i < out.size(); ++i) ASSERT_EQ(out[i], int(i) * 3 + 1) << threads << " threads";
  }
}

TEST(Parallel, TheLowestFailedIndexIsRethrownWhateverTheThreadCount) {
  for (int threads : {1, 2, 8}) {
    const Parallel parallel(threads);
    for (int repeat = 0; repeat < 20; ++repeat) {
      try {
        parallel.for_each(1000, [](std::size_t i) {
          if (i == 5 || i == 300 || i == 999) throw std::runtime_error("index " + std::to_string(i));
        });
        ADD_FAILURE() << "no exception";
      } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()), "index 5") << threads << " threads";
      }
    }
  }
}

TEST(Parallel, RunBesideRunsBothWithTheirOwnForEachAndSeesTheirWork) {
  for (int threads : {1, 2, 8}) {
    const Parallel parallel(threads);
    std::vector<int> a(3000, 0), b(2000, 0);
    parallel.run_beside([&] { parallel.for_each(a.size(), [&](std::size_t i) { a[i] = int(i) + 1; }); },
                        [&] { parallel.for_each(b.size(), [&](std::size_t i) { b[i] = 2 * int(i); }); });
    for (std::size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a[i], int(i) + 1) << threads << " threads";
    for (std::size_t i = 0; i < b.size(); ++i) ASSERT_EQ(b[i], 2 * int(i)) << threads << " threads";
  }
}

TEST(Parallel, RunBesideRethrowsTheFirstsExceptionWhenBothThrow) {
  for (int threads : {1, 2, 8}) {
    const Parallel parallel(threads);
    for (int repeat = 0; repeat < 20; ++repeat) {
      bool second_ran = false;
      try {
        parallel.run_beside([] { throw std::runtime_error("first"); },
                            [&] {
                              second_ran = true;
                              throw std::runtime_error("second");
                            });
        ADD_FAILURE() << "no exception";
      } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()), "first") << threads << " threads";
      }
      EXPECT_TRUE(second_ran) << threads << " threads";  // both always run
      try {
        parallel.run_beside([] {}, [] { throw std::runtime_error("second"); });
        ADD_FAILURE() << "no exception";
      } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()), "second") << threads << " threads";
      }
    }
  }
}

}  // namespace
}  // namespace tessref
