#pragma once
// The cheap baselines of the maximum clique searches: a greedy clique (a lower bound) and the
// greedy-colouring bound (an upper bound).

#include "antslam/clique/graph.hpp"

namespace antslam::clique {

/// Greedy maximal clique: starting from all vertices as candidates, repeatedly take the
/// candidate whose closed neighbourhood among the candidates weighs most (the most candidates
/// kept, for unit weights; lowest vertex on ties) and keep only its neighbours as candidates.
/// The result's upper_bound is colouring_bound(graph). O(clique size x n^2 / 64) for unit
/// weights.
CliqueResult greedy_clique(const Graph& graph);

/// Upper bound on the weight of any clique: colour the vertices greedily (by non-increasing
/// degree, each into the first colour class with no neighbour of it; Tomita & Seki 2003) and add
/// up the heaviest weight of every class, since a clique has at most one vertex per class. For
/// unit weights this is the number of colours.
double colouring_bound(const Graph& graph);

}  // namespace antslam::clique
