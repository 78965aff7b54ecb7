#pragma once
// Exact maximum (weighted) clique by branch and bound with a greedy-colouring bound: MCQ
// (Tomita & Seki 2003) in the bit-parallel form of BBMC (San Segundo, Rodriguez-Losada & Jimenez
// 2011). Vertices are renumbered by non-increasing degree; at every node the candidate set P is
// coloured greedily (colour classes of pairwise non-adjacent vertices, built word-wise), and the
// candidates are branched on in reverse colour order; a branch is cut when the current weight
// plus the heaviest-vertex weights of the colour classes up to the candidate's cannot beat the
// best clique so far. For unit weights the bound is the colour number of MCQ. The search starts
// from the greedy clique, or from a given clique unless the greedy one is heavier.

#include <cstdint>
#include <span>

#include "antslam/clique/graph.hpp"

namespace antslam::clique {

struct ExactSettings {
  double time_limit_s = 60.0;   ///< wall-clock budget in seconds; 0 = none
  std::uint64_t max_nodes = 0;  ///< budget in branch-and-bound nodes (deterministic); 0 = none
};

struct ExactResult {
  CliqueResult clique;      ///< optimal == true unless the budget ran out
  std::uint64_t nodes = 0;  ///< branch-and-bound nodes expanded
};

/// The maximum-weight clique, or, when a budget stops the search, the best clique found with
/// optimal == false and upper_bound from the colouring of the whole graph. `start`, a clique of
/// the graph, is the first incumbent unless the greedy clique is heavier (its weight then prunes
/// from the first node); only a heavier clique replaces it. Throws std::invalid_argument for a
/// negative or non-finite time limit or a `start` that is not a clique of the graph.
ExactResult maximum_clique_exact(const Graph& graph, const ExactSettings& settings = {},
                                 std::span<const std::uint32_t> start = {});

}  // namespace antslam::clique
