#pragma once
// Element-wise trail operations on a backend's threads. Evaporation, the pheromone bounds and the
// deposit of one solution change every trail entry at most once and read no other entry, so
// running disjoint chunks of them on several threads gives the same values, bit for bit, as one
// pass on one thread. Run serially, MAX-MIN's trail update is about 6 % of an iteration on
// 15,000 cities, a part that would not speed up with threads.

#include <algorithm>
#include <cstddef>
#include <functional>

#include "antslam/aco/backend.hpp"

namespace antslam::aco {

class ChunkedFor {
 public:
  /// Ranges shorter than two chunks of this many entries run on the calling thread: a fork-join
  /// costs a few microseconds, a chunk of this size a few more.
  static constexpr std::size_t kMinChunk = 16384;
  /// The same for ranges whose every index costs a search (the candidate-list lookups of a tour's
  /// deposit, tens of nanoseconds each).
  static constexpr std::size_t kMinSearchChunk = 1024;

  /// Runs every range on the calling thread.
  ChunkedFor() = default;

  /// Runs chunks on the backend's threads; the backend must outlive this object.
  template <Backend B>
  explicit ChunkedFor(B& backend)
      : threads_(backend.threads()),
        for_each_([&backend](std::size_t count, const std::function<void(std::size_t)>& f) {
          backend.for_each(count, f);
        }) {}

  /// Calls body(begin, end) once for each of disjoint ranges that cover [0, count) (in any order,
  /// possibly at the same time), each at least min_chunk long.
  template <class Body>
  void operator()(std::size_t count, Body&& body, std::size_t min_chunk = kMinChunk) const {
    const std::size_t chunks = threads_ < 2 ? 1 : std::min(4 * threads_, count / min_chunk);
    if (chunks < 2) {
      body(std::size_t{0}, count);
      return;
    }
    for_each_(chunks, [&](std::size_t c) { body(count * c / chunks, count * (c + 1) / chunks); });
  }

 private:
  std::size_t threads_ = 1;
  std::function<void(std::size_t, const std::function<void(std::size_t)>&)> for_each_;
};

}  // namespace antslam::aco
