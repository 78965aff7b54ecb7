#pragma once
// Graphs for the clique tests: random G(n, p) graphs with optional random weights and a planted
// clique, and the maximum clique weight by enumerating every subset.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "antslam/aco/random.hpp"
#include "antslam/clique/graph.hpp"

namespace antslam::clique::testing {

/// G(n, p), vertex weights uniform in {1, .., max_weight} (all 1 for max_weight = 1), and the
/// vertices `planted` made pairwise adjacent.
inline Graph random_graph(std::size_t n, double p, std::uint64_t seed, int max_weight = 1,
                          const std::vector<std::uint32_t>& planted = {}) {
  aco::Rng rng(aco::mix_seed(seed, 0xC11));
  std::vector<Edge> edges;
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = i + 1; j < n; ++j)
      if (rng.uniform() < p) edges.emplace_back(i, j);
  for (std::size_t a = 0; a < planted.size(); ++a)
    for (std::size_t b = a + 1; b < planted.size(); ++b) edges.emplace_back(planted[a], planted[b]);
  std::vector<double> weights;
  if (max_weight > 1)
    for (std::size_t v = 0; v < n; ++v)
      weights.push_back(1.0 + rng.below(static_cast<std::uint32_t>(max_weight)));
  return Graph(n, edges, weights);
}

/// The maximum clique weight by enumerating all 2^n vertex subsets (n <= 20).
inline double brute_force_maximum(const Graph& graph) {
  const std::size_t n = graph.size();
  double best = 0.0;
  std::vector<std::uint32_t> subset;
  for (std::uint32_t mask = 1; mask < (1U << n); ++mask) {
    subset.clear();
    for (std::uint32_t v = 0; v < n; ++v)
      if ((mask >> v) & 1U) subset.push_back(v);
    if (is_clique(graph, subset)) best = std::max(best, weight_of(graph, subset));
  }
  return best;
}

}  // namespace antslam::clique::testing
