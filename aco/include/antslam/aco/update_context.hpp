#pragma once
// What a pheromone-update policy sees. A policy provides
//   initialize(trail, InitContext)   set the initial trail (Algorithm 2, lines 4-6);
//   apply(trail, IterationView)      the end-of-iteration update (Algorithm 2, lines 29-34);
// and, for Ant Colony System only, local_update(tau) applied as ants move.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>

#include "antslam/aco/chunked_for.hpp"
#include "antslam/aco/solution.hpp"

namespace antslam::aco {

struct InitContext {
  double reference_cost = 1.0;  ///< cost of the greedy solution (C_nn for TSP)
  std::size_t ants = 1;         ///< ants per iteration
  std::size_t decisions = 1;    ///< decisions per solution (cities; layers)
  double mean_options = 2.0;    ///< mean number of options per decision
  bool local_search = false;    ///< whether a local search improves the ants
  bool focused = false;         ///< whether ants change a source tour (focused_construction.hpp)
  double max_options = 2.0;     ///< options of the widest decision (TSP: candidate-list length)
};

struct IterationView {
  std::span<const Solution> ants;          ///< this iteration's ants, in ant order
  std::span<const std::uint32_t> ranking;  ///< ant indices by increasing cost, ties by index
  const Solution& iteration_best;
  const Solution& global_best;
  std::uint64_t iteration = 0;  ///< number of iterations completed, this one included
  ChunkedFor parallel = {};     ///< runs the trail's element-wise updates (chunked_for.hpp)
};

/// q / cost, guarded against a zero cost (eq. 3 and eq. 12).
inline double deposit_amount(double q, double cost) { return q / std::max(cost, 1e-12); }

template <class U>
concept HasLocalUpdate = requires(const U& u, double& tau) {
  u.local_update(tau);
};

}  // namespace antslam::aco
