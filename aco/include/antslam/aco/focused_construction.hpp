#pragma once
// Focused construction (Skinderowicz 2022, "Improving Ant Colony Optimization efficiency for
// solving large TSP instances", Applied Soft Computing 120, the construction of FocusedACO): an
// ant does not build its tour from nothing but changes a source tour, the iteration-best or the
// best-so-far tour. It walks from a random start city choosing with the construction rule as
// usual; once it has introduced `min_new_edges` edges that are not in the source, every time it
// stands on a city it copies the source's path from there, in the direction whose next city is
// still unvisited, until it meets a visited city, and then chooses once more with the rule. So
// the rule is consulted O(changes) times once pheromone has converged on the source, instead of
// n times, and the ant's tour differs from the source in a few edges, whose endpoints are the
// only cities a local search has to start from.
//
// The engine offers it to every variant for permutation problems (ColonySettings::focused);
// it runs only when a source exists, i.e. from the second iteration on.

#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

namespace antslam::aco {

struct FocusedSettings {
  std::size_t min_new_edges = 0;     ///< edges an ant adds before it copies the source; 0 = off
  double global_best_source = 0.01;  ///< probability that the source is the best-so-far tour
                                     ///< rather than the previous iteration's best (FocusedACO)
  bool enabled() const { return min_new_edges > 0; }
};

/// The source tour as successor and predecessor arrays: adjacency in O(1).
class SourceTour {
 public:
  void assign(std::span<const std::uint32_t> tour) {
    const std::size_t n = tour.size();
    succ_.resize(n);
    pred_.resize(n);
    for (std::size_t p = 0; p < n; ++p) {
      const std::uint32_t next = tour[p + 1 == n ? 0 : p + 1];
      if (tour[p] >= n || next >= n) throw std::invalid_argument("source tour: bad city id");
      succ_[tour[p]] = next;
      pred_[next] = tour[p];
    }
  }
  bool empty() const { return succ_.empty(); }
  std::uint32_t next(std::uint32_t c, bool forward) const { return forward ? succ_[c] : pred_[c]; }
  /// Whether (a, b) is an edge of the source, in either direction.
  bool adjacent(std::uint32_t a, std::uint32_t b) const { return succ_[a] == b || pred_[a] == b; }

 private:
  std::vector<std::uint32_t> succ_;
  std::vector<std::uint32_t> pred_;
};

/// Builds one focused tour of n cities from `start`. The caller's construction state is reached
/// through three callables: choose(current) draws the next city with the construction rule,
/// visit(city) appends a city to the tour, visited(city) tells whether it is in the tour already.
/// Every edge not in the source is appended to `new_edges` as two cities (the closing edge
/// included), so new_edges.size() / 2 is the number of changed edges.
template <class Choose, class Visit, class Visited>
void build_focused(const SourceTour& source, std::uint32_t n, std::uint32_t start,
                   std::size_t min_new_edges, Choose&& choose, Visit&& visit, Visited&& visited,
                   std::vector<std::uint32_t>& new_edges) {
  new_edges.clear();
  const auto record = [&](std::uint32_t a, std::uint32_t b) {
    if (source.adjacent(a, b)) return;
    new_edges.push_back(a);
    new_edges.push_back(b);
  };
  visit(start);
  std::uint32_t placed = 1;
  std::uint32_t current = start;
  while (placed < n) {
    const std::uint32_t next = choose(current);
    visit(next);
    ++placed;
    record(current, next);
    current = next;
    if (new_edges.size() / 2 < min_new_edges) continue;
    for (const bool forward : {true, false}) {
      std::uint32_t follow = source.next(current, forward);
      if (visited(follow)) continue;
      do {
        visit(follow);
        ++placed;
        current = follow;
        follow = source.next(follow, forward);
      } while (!visited(follow));
      break;
    }
  }
  record(current, start);
}

}  // namespace antslam::aco
