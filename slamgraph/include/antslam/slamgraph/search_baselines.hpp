#pragma once
// Discrete baselines on the same tree of samples: exhaustive search, which proves
// optimality on small sets, and uniform random sampling, which shows what the ants add at the
// same evaluation budget.

#include <cstdint>
#include <functional>
#include <stop_token>
#include <vector>

#include "antslam/slamgraph/fragment_set.hpp"
#include "antslam/slamgraph/slam_problem.hpp"

namespace antslam::slam {

struct SearchResult {
  std::vector<std::uint32_t> choice;  ///< best sample of every fragment 2..N
  double weight = 0.0;                ///< its eq. (10) weight
  std::uint64_t evaluations = 0;      ///< complete paths whose weight was computed
};

/// Number of paths through the tree, prod_i M_i (eq. 13's M^{N-1}); saturates at UINT64_MAX.
std::uint64_t path_count(const FragmentSet& set);

/// The exact minimum of eq. (10) over all M^{N-1} paths, by depth-first search with the chain
/// of eq. (8) built incrementally. Every term of eq. (10) is >= 0, so a partial path whose
/// weight already reaches the best complete one is cut (branch and bound). Ties keep the
/// lexicographically first path. Throws std::invalid_argument if path_count(set) > max_paths.
SearchResult exhaustive_search(const FragmentSet& set, std::uint64_t max_paths);

/// Called with (iteration, evaluations, best weight) whenever the best path improves.
using SearchObserver = std::function<void(std::uint64_t, std::uint64_t, double)>;

/// Uniform random sampling at the ants' budget: in each of `iterations` rounds, `paths` paths
/// are drawn uniformly (path p of round t from aco::ant_stream(seed, t, p), so the result does
/// not depend on threads) and the best is kept. Stops early after `time_limit_s` (0 = none), or
/// after the round in which `stop` is requested; 0 rounds means no limit on rounds (then a time
/// limit is required). At least one round runs.
SearchResult random_search(const SlamProblem& problem, std::uint64_t iterations, std::size_t paths,
                           std::uint64_t seed, double time_limit_s,
                           const SearchObserver& observer = {}, std::stop_token stop = {});

}  // namespace antslam::slam
