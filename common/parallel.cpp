#include "common/parallel.h"

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace tessref {

// More threads than the hardware has would only oversubscribe (and make TBB warn); results never
// depend on the count, so asking for more simply gets all there are.
Parallel::Parallel(int threads)
    : threads_(threads > 0 ? std::min(threads, tbb::info::default_concurrency())
                           : tbb::info::default_concurrency()),
      arena_(threads_ > 1 ? std::make_shared<tbb::task_arena>(threads_) : nullptr) {}

void Parallel::for_each(std::size_t n, const std::function<void(std::size_t)>& fn) const {
  if (threads_ == 1 || n <= 1) {
    for (std::size_t i = 0; i < n; ++i) fn(i);
    return;
  }
  arena_->execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t i = r.begin(); i != r.end(); ++i) fn(i);
                      });
  });
}

}  // namespace tessref
