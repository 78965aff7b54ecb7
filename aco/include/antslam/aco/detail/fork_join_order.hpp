#pragma once
// The fork-join order of a parallel loop, told to ThreadSanitizer. TSan sees it only through an
// instrumented threading runtime, and Debian's libtbb and LLVM's libomp are not instrumented, so
// the backends announce it themselves: everything the caller did before the loop happens before
// every iteration (fork), and every iteration happens before what follows the loop (join).
// Iterations stay unordered among themselves, so a race between two ants is still reported.
// Without -fsanitize=thread every call is empty.

#if defined(__SANITIZE_THREAD__)
#define ANTSLAM_THREAD_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define ANTSLAM_THREAD_SANITIZER 1
#endif
#endif

#ifdef ANTSLAM_THREAD_SANITIZER
#include <sanitizer/tsan_interface.h>
#endif

namespace antslam::aco::detail {

class ForkJoinOrder {
 public:
  /// The caller, before the loop starts.
  void fork() { release(&fork_); }
  /// The caller, after the loop has finished.
  void join() { acquire(&join_); }

  /// Marks one iteration: ordered after fork() from construction, before join() at destruction.
  class Iteration {
   public:
    explicit Iteration(ForkJoinOrder& order) : order_(order) { acquire(&order_.fork_); }
    ~Iteration() { release(&order_.join_); }
    Iteration(const Iteration&) = delete;
    Iteration& operator=(const Iteration&) = delete;

   private:
    ForkJoinOrder& order_;
  };

 private:
  static void acquire([[maybe_unused]] void* address) {
#ifdef ANTSLAM_THREAD_SANITIZER
    __tsan_acquire(address);
#endif
  }
  static void release([[maybe_unused]] void* address) {
#ifdef ANTSLAM_THREAD_SANITIZER
    __tsan_release(address);
#endif
  }

  char fork_ = 0;
  char join_ = 0;
};

}  // namespace antslam::aco::detail
