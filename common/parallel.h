#pragma once
// One small parallel wrapper over oneTBB. Work is split into fixed, index-addressed chunks;
// callers write results into preassigned slots, so results never depend on the thread count.
#include <cstddef>
#include <functional>
#include <memory>

namespace tbb::detail::d1 {
class task_arena;
class global_control;
}

namespace tessref {

class Parallel {
 public:
  // threads <= 0: all hardware threads.
  explicit Parallel(int threads = 0);
  int threads() const { return threads_; }
  // Calls fn(i) for every i in [0, n), on up to threads() threads, in no particular order. If calls
  // throw, the exception of the lowest such i is rethrown, whatever the thread count (calls past a
  // failed i are skipped once it failed), so errors are as deterministic as results.
  void for_each(std::size_t n, const std::function<void(std::size_t)>& fn) const;
  // Runs first() and second() at the same time (each may call for_each; their tasks share the
  // threads), or one after the other on one thread. They must not touch the same data. Both always
  // run to their end; if both throw, first()'s exception is rethrown.
  void run_beside(const std::function<void()>& first, const std::function<void()>& second) const;

 private:
  int threads_;
  // One arena for the object's lifetime: creating one per call is slow and makes TBB warn.
  std::shared_ptr<tbb::detail::d1::task_arena> arena_;
  std::shared_ptr<tbb::detail::d1::global_control> oversubscribe_;
};

}  // namespace tessref
