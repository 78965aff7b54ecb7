#pragma once
// OpenMP backend. Link antslam::aco_omp.

#include <omp.h>

#include <cstddef>
#include <exception>
#include <mutex>

#include "antslam/aco/backend_kind.hpp"
#include "antslam/aco/detail/fork_join_order.hpp"

namespace antslam::aco {

class OmpBackend {
 public:
  /// threads == 0: OpenMP's default (OMP_NUM_THREADS or the number of cores).
  explicit OmpBackend(std::size_t threads = 0)
      : threads_(threads == 0 ? static_cast<std::size_t>(omp_get_max_threads()) : threads) {}

  BackendKind kind() const { return BackendKind::omp; }
  std::size_t threads() const { return threads_; }

  template <class F>
  void for_each(std::size_t count, F&& f) {
    std::exception_ptr error;
    std::mutex error_mutex;
    const auto n = static_cast<long long>(count);
    detail::ForkJoinOrder order;
    order.fork();
#pragma omp parallel for schedule(dynamic, 1) num_threads(static_cast <int>(threads_))
    for (long long i = 0; i < n; ++i) {
      const detail::ForkJoinOrder::Iteration iteration(order);
      try {
        f(static_cast<std::size_t>(i));
      } catch (...) {
        const std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
      }
    }
    order.join();
    if (error) std::rethrow_exception(error);
  }

 private:
  std::size_t threads_;
};

}  // namespace antslam::aco
