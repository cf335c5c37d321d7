#include "common/parallel.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace tessref {

Parallel::Parallel(int threads)
    : threads_(threads > 0 ? threads : tbb::info::default_concurrency()),
      arena_(threads_ > 1 ? std::make_shared<tbb::task_arena>(threads_) : nullptr) {
  // More threads than the hardware has are allowed (tests oversubscribe on purpose to show the
  // result does not depend on the count); TBB must be told, or it caps the workers and warns.
  if (threads_ > tbb::info::default_concurrency())
    oversubscribe_ = std::make_shared<tbb::global_control>(
        tbb::global_control::max_allowed_parallelism, std::size_t(threads_));
}

void Parallel::for_each(std::size_t n, const std::function<void(std::size_t)>& fn) const {
  if (threads_ == 1 || n <= 1) {
    for (std::size_t i = 0; i < n; ++i) fn(i);
    return;
  }
  std::mutex mutex;
  std::atomic<std::size_t> first_failed{n};
  std::exception_ptr error;
  arena_->execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t i = r.begin(); i != r.end(); ++i) {
                          if (i > first_failed.load(std::memory_order_relaxed)) return;
                          try {
                            fn(i);
                          } catch (...) {
                            const std::lock_guard<std::mutex> lock(mutex);
                            if (i < first_failed) {
                              first_failed = i;
                              error = std::current_exception();
                            }
                          }
                        }
                      });
  });
  if (error) std::rethrow_exception(error);
}

}  // namespace tessref
