#pragma once
// Local search for the ants' cliques: (1,2)-swaps, the move of Andrade, Resende & Werneck's
// iterated local search for maximum independent sets (2012) seen on the complement graph. A
// non-member is 1-tight when it is adjacent to every member but one, v; two adjacent 1-tight
// vertices u, w of the same v replace v when w(u) + w(w) > w(v). After each swap every vertex
// adjacent to the whole clique is added (lowest first), so the clique stays maximal and never
// gets lighter. Then, if plateau_steps > 0, a plateau walk (the plateau moves of Grosso,
// Locatelli & Pullan 2008): the lowest 1-tight vertex u with w(u) >= w(v) replaces its v, v is
// barred from coming back for the rest of the walk, and the (1,2)-swaps run again; after at most
// plateau_steps such moves, or when none is left, the heaviest clique met (the first of its
// weight) is kept, so a walk that gains nothing changes nothing. Deterministic: the random stream
// is not used.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "antslam/aco/random.hpp"
#include "antslam/aco/termination.hpp"
#include "antslam/clique/problem.hpp"

namespace antslam::clique {

class SwapLocalSearch {
 public:
  struct Workspace {
    std::vector<std::uint64_t> members;  // the clique as a bit set
    std::vector<std::uint32_t> tight;    // 1-tight non-members
    std::vector<std::uint32_t> missing;  // the member each one misses
    std::vector<std::uint32_t> order;    // tight sorted by (missing, vertex)
    std::vector<std::uint64_t> barred;   // members swapped out on the plateau walk
    std::vector<std::uint32_t> best;     // the heaviest clique of the walk
  };

  std::size_t plateau_steps = 0;  ///< plateau moves after the (1,2)-swaps; 0 = none

  Workspace make_workspace(const CliqueProblem& problem) const;

  /// Improves the maximal clique `clique` in place until no (1,2)-swap gains weight, then by the
  /// plateau walk; `stop` ends either early.
  void improve(const CliqueProblem& problem, std::vector<std::uint32_t>& clique, Workspace& ws,
               aco::Rng& rng, const aco::StopToken& stop) const;
};

}  // namespace antslam::clique
