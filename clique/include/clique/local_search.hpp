#pragma once
// Local search for the ants' cliques: (1,2)-swaps, the move of Andrade, Resende & Werneck's
// iterated local search for maximum independent sets (2012) seen on the complement graph. A
// non-member is 1-tight when it is adjacent to every member but one, v; two adjacent 1-tight
// vertices u, w of the same v replace v when w(u) + w(w) > w(v). After each swap every vertex
// adjacent to the whole clique is added (lowest first), so the clique stays maximal and never
// gets lighter. Deterministic: the random stream is not used.

#include <cstdint>
#include <vector>

#include "aco/random.hpp"
#include "aco/termination.hpp"
#include "clique/problem.hpp"

namespace antslam::clique {

class SwapLocalSearch {
 public:
  struct Workspace {
    std::vector<std::uint64_t> members;  // the clique as a bit set
    std::vector<std::uint32_t> tight;    // 1-tight non-members
    std::vector<std::uint32_t> missing;  // the member each one misses
    std::vector<std::uint32_t> order;    // tight sorted by (missing, vertex)
  };

  Workspace make_workspace(const CliqueProblem& problem) const;

  /// Improves the maximal clique `clique` in place until no (1,2)-swap gains weight or `stop`
  /// expires.
  void improve(const CliqueProblem& problem, std::vector<std::uint32_t>& clique, Workspace& ws,
               aco::Rng& rng, const aco::StopToken& stop) const;
};

}  // namespace antslam::clique
