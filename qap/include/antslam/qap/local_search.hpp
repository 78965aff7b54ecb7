#pragma once
// Pair-swap (2-exchange) local search for the QAP, best improvement: every iteration evaluates
// the swap of the locations of every pair of facilities and applies the best one, until no swap
// lowers the cost (the local search of MMAS-QAP, Stuetzle & Hoos 2000). A swap's change of cost
// is computed in O(n) by Taillard's formula (1991), valid for asymmetric matrices, so a full
// neighbourhood scan costs O(n^3).

#include <cstdint>
#include <span>
#include <vector>

#include "antslam/aco/random.hpp"
#include "antslam/aco/termination.hpp"
#include "antslam/qap/instance.hpp"
#include "antslam/qap/problem.hpp"

namespace antslam::qap {

/// cost(p with p[r] and p[s] swapped) - cost(p), r != s (Taillard 1991).
std::int64_t swap_delta(const Instance& instance, std::span<const std::uint32_t> p, std::uint32_t r,
                        std::uint32_t s);

class PairSwapLocalSearch {
 public:
  struct Workspace {};

  Workspace make_workspace(const QapProblem&) const { return {}; }

  /// Improves the assignment in place until it is 2-exchange optimal; `stop` ends it early,
  /// between two scans of the neighbourhood. The random stream is not used.
  void improve(const QapProblem& problem, std::vector<std::uint32_t>& assignment, Workspace&,
               aco::Rng&, const aco::StopToken& stop) const;
};

}  // namespace antslam::qap
