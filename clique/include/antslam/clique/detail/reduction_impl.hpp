#pragma once
// maximum_clique_reduced (clique/reduction.hpp).

#include <algorithm>
#include <cstddef>

namespace antslam::clique {

template <class Search>
CliqueResult maximum_clique_reduced(const Graph& graph, const CliqueReduction& reduction,
                                    Search&& search) {
  CliqueResult result;
  result.vertices = reduction.universal;
  const auto universal = static_cast<double>(reduction.universal.size());
  if (reduction.residual.empty()) {
    result.upper_bound = universal;
    result.optimal = true;
  } else {
    const CliqueResult found = search(induced_subgraph(graph, reduction.residual));
    for (const std::uint32_t v : found.vertices) result.vertices.push_back(reduction.residual[v]);
    std::sort(result.vertices.begin(), result.vertices.end());
    result.upper_bound = universal + found.upper_bound;
    result.optimal = found.optimal;
    result.elapsed_s = found.elapsed_s;
  }
  if (reduction.greedy.size() > result.vertices.size()) result.vertices = reduction.greedy;
  result.weight = static_cast<double>(result.vertices.size());
  result.upper_bound = std::max(result.upper_bound, result.weight);
  result.optimal = result.optimal || result.weight == result.upper_bound;
  return result;
}

}  // namespace antslam::clique
