#pragma once
// TSP local search as an engine policy (aco::LocalSearchFor): improves an ant's tour after
// construction, as in Stuetzle's ACOTSP.
//
//   2opt    2-opt moves (Croes 1958)
//   2.5opt  2-opt plus node insertion (Bentley 1992's "2h-opt")
//   3opt    sequential 3-opt (Lin 1965): every reconnection of three removed edges reachable
//           by a sequential exchange, including the pure segment moves of Or-opt
//
// All three use nearest-neighbour lists (a new edge joins a city to one of its `neighbours`
// nearest), the gain criterion (each partial exchange must gain), first improvement, moves as
// reversals of the shorter side of the tour (an array tour with a position index, O(n) a move;
// from `two_level_from` cities a two-level tour, O(sqrt n) a move), and don't-look bits as a
// queue of the cities whose tour edges changed (Bentley 1992). Every move strictly shortens
// the tour, so the tour never gets longer. The stop token is polled every 64 queue steps.
//
// queue_changed_only: a workspace remembers the tour it returned last (the same ant slot's
// previous local optimum); the next search starts with only the cities that have a tour edge not
// in it. With false every city starts active, as in ACOTSP.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "antslam/aco/random.hpp"
#include "antslam/aco/termination.hpp"
#include "antslam/tsp/array_tour.hpp"
#include "antslam/tsp/problem.hpp"
#include "antslam/tsp/two_level_tour.hpp"

namespace antslam::tsp {

enum class LocalSearchKind { none, two_opt, two_half_opt, three_opt };

std::string_view to_string(LocalSearchKind kind);
/// "none", "2opt", "2.5opt", "3opt".
std::optional<LocalSearchKind> parse_local_search(std::string_view name);

struct LocalSearchSettings {
  LocalSearchKind kind = LocalSearchKind::three_opt;  ///< neighbourhood; none leaves tours as built
  std::size_t neighbours = 20;     ///< nearest neighbours tried per city (count; capped by lists)
  bool queue_changed_only = true;  ///< start from cities with an edge not in the last result
  std::size_t two_level_from = 30'000;  ///< cities from which moves run on a TwoLevelTour
};

/// What one improve() call did (for tests and benchmarks).
struct LocalSearchStats {
  std::uint64_t moves = 0;     ///< improving moves applied
  std::uint64_t examined = 0;  ///< cities taken from the don't-look queue
  bool stopped = false;        ///< the stop token ended the search early
};

class TourLocalSearch {
 public:
  /// One per ant, a cache line of its own (ants on different threads update theirs constantly).
  struct alignas(64) Workspace {
    ArrayTour tour;                       // the tour while moves run, below two_level_from cities
    TwoLevelTour large;                   // the tour while moves run, from two_level_from cities
    std::vector<std::uint32_t> previous;  // the last tour returned, with queue_changed_only
    std::vector<std::uint32_t> previous_position;  // city -> its place in `previous`
    std::vector<std::uint32_t> queue;  // circular FIFO of cities whose don't-look bit is off
    std::vector<std::uint8_t> queued;
    LocalSearchStats stats;  // of the last improve() call
  };

  explicit TourLocalSearch(const LocalSearchSettings& settings = {}) : settings_(settings) {}

  const LocalSearchSettings& settings() const { return settings_; }

  Workspace make_workspace(const TspProblem& problem) const;

  /// Improves `tour` (a permutation of the problem's cities) to a local optimum of the chosen
  /// neighbourhood, or until `stop` expires. Cities are examined first in a random order drawn
  /// from `rng`.
  void improve(const TspProblem& problem, std::vector<std::uint32_t>& tour, Workspace& workspace,
               aco::Rng& rng, const aco::StopToken& stop) const;

  /// The same search started from the endpoints of `new_edges` only (city pairs: the edges of
  /// `tour` that are not in a local optimum of this neighbourhood, as a focused construction
  /// reports them; aco::LocalSearchFromCities). Apart from copying the tour it costs O(changes).
  void improve(const TspProblem& problem, std::vector<std::uint32_t>& tour, Workspace& workspace,
               aco::Rng& rng, const aco::StopToken& stop,
               std::span<const std::uint32_t> new_edges) const;

 private:
  /// Resets the stats; false when there is nothing to search.
  bool begin(const TspProblem& problem, const std::vector<std::uint32_t>& tour,
             Workspace& workspace) const;
  /// Loads `tour`, runs the don't-look-bit queue (its first `count` entries active) on the
  /// representation for its size and writes the result back.
  void search(const TspProblem& problem, std::vector<std::uint32_t>& tour, Workspace& workspace,
              std::uint32_t count, const aco::StopToken& stop) const;
  template <class Tour>
  void run_queue(const TspProblem& problem, Tour& moves_on, Workspace& workspace,
                 std::uint32_t count, const aco::StopToken& stop) const;

  LocalSearchSettings settings_;
};

}  // namespace antslam::tsp
