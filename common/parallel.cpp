#include "common/parallel.h"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace tessref {

Parallel::Parallel(int threads)
    : threads_(threads > 0 ? threads : tbb::info::default_concurrency()) {}

void Parallel::for_each(std::size_t n, const std::function<void(std::size_t)>& fn) const {
  if (threads_ == 1 || n <= 1) {
    for (std::size_t i = 0; i < n; ++i) fn(i);
    return;
  }
  tbb::task_arena arena(threads_);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t i = r.begin(); i != r.end(); ++i) fn(i);
                      });
  });
}

}  // namespace tessref
