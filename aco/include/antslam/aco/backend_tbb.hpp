#pragma once
// oneTBB backend. Link antslam::aco_tbb.

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cstddef>
#include <memory>

#include "antslam/aco/backend_kind.hpp"
#include "antslam/aco/detail/fork_join_order.hpp"

namespace antslam::aco {

class TbbBackend {
 public:
  /// threads == 0: TBB's default concurrency.
  explicit TbbBackend(std::size_t threads = 0)
      : arena_(std::make_shared<tbb::task_arena>(threads == 0 ? tbb::task_arena::automatic
                                                              : static_cast<int>(threads))) {
    arena_->initialize();
  }

  BackendKind kind() const { return BackendKind::tbb; }
  std::size_t threads() const { return static_cast<std::size_t>(arena_->max_concurrency()); }

  template <class F>
  void for_each(std::size_t count, F&& f) {
    detail::ForkJoinOrder order;
    order.fork();
    arena_->execute([&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1),
                        [&](const tbb::blocked_range<std::size_t>& range) {
                          const detail::ForkJoinOrder::Iteration iteration(order);
                          for (std::size_t i = range.begin(); i != range.end(); ++i) f(i);
                        });
    });
    order.join();
  }

 private:
  std::shared_ptr<tbb::task_arena> arena_;
};

}  // namespace antslam::aco
