#include "common/parallel.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>

// ThreadSanitizer (scripts/sanitize.sh tsan) and oneTBB: Debian's libtbb is not instrumented, so
// TSan does not see the synchronization inside it (spawning, stealing, waiting) and would report
// every write made before for_each and read in a task, or made in a task and read after for_each,
// as a data race. Under TSan, for_each states what tbb::parallel_for guarantees: everything
// before it happens before every task, and every task happens before it returns (two
// happens-before edges through two synchronization objects). Races between two tasks stay
// visible: no task acquires what another released. A task reads what TBB handed it in its task
// object (its copy of the closure, its range) unseen by TSan, as TBB publishes tasks inside the
// library. Without TSan all of this compiles to nothing. scripts/sanitizer/tsan.supp drops the
// reports about TBB's own objects.
#if defined(__SANITIZE_THREAD__)
#define TESSREF_TSAN 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define TESSREF_TSAN 1
#endif
#endif
#ifdef TESSREF_TSAN
extern "C" void __tsan_acquire(void* addr);
extern "C" void __tsan_release(void* addr);
extern "C" void AnnotateIgnoreReadsBegin(const char* file, int line);
extern "C" void AnnotateIgnoreReadsEnd(const char* file, int line);
#endif

namespace tessref {
namespace {

void happens_before_release([[maybe_unused]] void* sync) {
#ifdef TESSREF_TSAN
  __tsan_release(sync);
#endif
}

void happens_before_acquire([[maybe_unused]] void* sync) {
#ifdef TESSREF_TSAN
  __tsan_acquire(sync);
#endif
}

template <typename T>
T read_handed_over(const T& value) {
#ifdef TESSREF_TSAN
  AnnotateIgnoreReadsBegin(__FILE__, __LINE__);
  const T copy = value;
  AnnotateIgnoreReadsEnd(__FILE__, __LINE__);
  return copy;
#else
  return value;
#endif
}

}  // namespace

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
  // What the tasks share, on this stack; each task's closure holds only its address.
  struct Shared {
    const std::function<void(std::size_t)>& fn;
    std::mutex mutex;
    std::atomic<std::size_t> first_failed;
    std::exception_ptr error;
    char start = 0, end = 0;  // TSan's synchronization objects (only their addresses count)
  } shared{fn, {}, n, {}};
  Shared* const state = &shared;
  happens_before_release(&shared.start);
  arena_->execute([n, state] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1),
                      [state](const tbb::blocked_range<std::size_t>& task_range) {
                        Shared& s = *read_handed_over(state);
                        const tbb::blocked_range<std::size_t> r = read_handed_over(task_range);
                        happens_before_acquire(&s.start);
                        for (std::size_t i = r.begin(); i != r.end(); ++i) {
                          if (i > s.first_failed.load(std::memory_order_relaxed)) break;
                          try {
                            s.fn(i);
                          } catch (...) {
                            const std::lock_guard<std::mutex> lock(s.mutex);
                            if (i < s.first_failed) {
                              s.first_failed = i;
                              s.error = std::current_exception();
                            }
                          }
                        }
                        happens_before_release(&s.end);
                      });
  });
  happens_before_acquire(&shared.end);
  if (shared.error) std::rethrow_exception(shared.error);
}

void Parallel::run_beside(const std::function<void()>& first, const std::function<void()>& second) const {
  struct Shared {
    const std::function<void()>* fn[2];
    std::exception_ptr error[2];
    char start = 0, end = 0;  // TSan's synchronization objects, as in for_each
  } shared{{&first, &second}, {}};
  Shared* const state = &shared;
  auto task = [state](int k) {  // runs to its end whatever the other does
    Shared& s = *read_handed_over(state);
    happens_before_acquire(&s.start);
    try {
      (*s.fn[k])();
    } catch (...) {
      s.error[k] = std::current_exception();
    }
    happens_before_release(&s.end);
  };
  happens_before_release(&shared.start);
  if (threads_ == 1) {
    task(0);
    task(1);
  } else {
    arena_->execute([&task] { tbb::parallel_invoke([&task] { task(0); }, [&task] { task(1); }); });
  }
  happens_before_acquire(&shared.end);
  for (const std::exception_ptr& e : shared.error)
    if (e) std::rethrow_exception(e);
}

}  // namespace tessref
