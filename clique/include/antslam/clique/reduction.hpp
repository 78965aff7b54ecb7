#pragma once
// What a maximum clique search must look at (the pruning of PMC, Rossi et al. 2015), for unit
// weights: a greedy clique of L vertices is a lower bound; a vertex of degree < L - 1 is in no
// clique of L or more vertices, so such vertices are removed until none is left (a k-core); a
// vertex then adjacent to every other vertex left is in every maximum clique of what is left.
// A maximum clique of the graph is those universal vertices plus a maximum clique of the rest
// (the residual), which is all a search needs to see. On a consistency graph of thousands of
// loop closures that agree with each other but for a few pairs, the residual is a few hundred
// vertices.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "antslam/clique/graph.hpp"

namespace antslam::clique {

struct CliqueReduction {
  std::vector<std::uint32_t> greedy;     ///< the greedy clique (by degree), increasing
  std::vector<std::uint32_t> universal;  ///< in every maximum clique, increasing
  std::vector<std::uint32_t> residual;   ///< the vertices left to search, increasing
};

/// The reduction above. Throws std::invalid_argument for weighted graphs (the degree bound holds
/// for cardinality only).
CliqueReduction reduce_for_maximum_clique(const Graph& graph);

/// The subgraph induced by `vertices` (increasing, distinct): its vertex i is vertices[i], with
/// that vertex's weight.
Graph induced_subgraph(const Graph& graph, std::span<const std::uint32_t> vertices);

/// A maximum clique by `search` (a function Graph -> CliqueResult, e.g. branch and bound or the
/// ants) run on the residual only: the universal vertices plus the residual's clique mapped back,
/// or the greedy clique if that is larger; upper_bound adds the universal vertices to the
/// residual's bound. An empty residual needs no search: the universal vertices are the maximum.
template <class Search>
CliqueResult maximum_clique_reduced(const Graph& graph, const CliqueReduction& reduction,
                                    Search&& search);

}  // namespace antslam::clique

#include "antslam/clique/detail/reduction_impl.hpp"
