#include "antslam/clique/greedy.hpp"

#include <algorithm>
#include <chrono>

#include "bits.hpp"
#include "colouring.hpp"

namespace antslam::clique {

CliqueResult greedy_clique(const Graph& graph) {
  const auto start = std::chrono::steady_clock::now();
  CliqueResult result;
  detail::Bits candidates = detail::all_bits(graph.size());
  while (detail::any(candidates)) {
    std::uint32_t best = 0;
    double best_score = -1.0;
    detail::for_each_bit(candidates, [&](std::uint32_t v) {
      double score = graph.weight(v);
      if (graph.unit_weights()) {
        score += static_cast<double>(detail::count_and(candidates, graph.row(v)));
      } else {
        detail::for_each_bit(candidates, [&](std::uint32_t u) {
          if (graph.adjacent(v, u)) score += graph.weight(u);
        });
      }
      if (score > best_score) {
        best_score = score;
        best = v;
      }
    });
    result.vertices.push_back(best);
    const auto row = graph.row(best);
    for (std::size_t k = 0; k < candidates.size(); ++k) candidates[k] &= row[k];
  }
  std::sort(result.vertices.begin(), result.vertices.end());
  result.weight = weight_of(graph, result.vertices);
  result.upper_bound = colouring_bound(graph);
  result.optimal = result.weight >= result.upper_bound;
  result.elapsed_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

double colouring_bound(const Graph& graph) {
  const detail::RenumberedGraph renumbered(graph);
  detail::Bits remaining, open;
  std::vector<std::uint32_t> order;
  std::vector<double> bound;
  detail::colour(renumbered, detail::all_bits(graph.size()), remaining, open, order, bound);
  return bound.empty() ? 0.0 : bound.back();
}

}  // namespace antslam::clique
