#include "antslam/clique/reduction.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "bits.hpp"

namespace antslam::clique {

namespace {

/// A clique by taking the vertices in order of decreasing degree (lowest index on ties), each
/// one adjacent to all taken so far: one word-wise AND per vertex taken, where greedy_clique
/// (greedy.hpp) recounts every candidate's neighbours at each step, O(n^2 / 64) a vertex taken
/// (minutes on the 10,688 closures of city10000).
std::vector<std::uint32_t> greedy_by_degree(const Graph& graph) {
  std::vector<std::uint32_t> order(graph.size());
  std::iota(order.begin(), order.end(), 0U);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return graph.degree(a) > graph.degree(b);
  });
  std::vector<std::uint64_t> candidates(graph.words(), ~std::uint64_t{0});
  std::vector<std::uint32_t> clique;
  for (const std::uint32_t v : order) {
    if (((candidates[v >> 6U] >> (v & 63U)) & 1U) == 0) continue;
    clique.push_back(v);
    const std::span<const std::uint64_t> row = graph.row(v);
    for (std::size_t w = 0; w < candidates.size(); ++w) candidates[w] &= row[w];
  }
  std::sort(clique.begin(), clique.end());
  return clique;
}

}  // namespace

CliqueReduction reduce_for_maximum_clique(const Graph& graph) {
  if (!graph.unit_weights())
    throw std::invalid_argument("clique reduction: the degree bound needs unit weights");
  CliqueReduction reduction;
  const std::size_t n = graph.size();
  if (n == 0) return reduction;
  reduction.greedy = greedy_by_degree(graph);
  // The k-core for k = L - 1: remove vertices of degree < L - 1 until none is left.
  const std::size_t need = reduction.greedy.size() - 1;
  std::vector<std::size_t> degree(n);
  std::vector<bool> removed(n, false);
  std::vector<std::uint32_t> queue;
  for (std::uint32_t v = 0; v < n; ++v) {
    degree[v] = graph.degree(v);
    if (degree[v] < need) {
      removed[v] = true;
      queue.push_back(v);
    }
  }
  while (!queue.empty()) {
    const std::uint32_t v = queue.back();
    queue.pop_back();
    for (const std::uint32_t u : graph.neighbours(v)) {
      if (removed[u]) continue;
      if (--degree[u] < need) {
        removed[u] = true;
        queue.push_back(u);
      }
    }
  }
  const auto left = static_cast<std::size_t>(std::count(removed.begin(), removed.end(), false));
  for (std::uint32_t v = 0; v < n; ++v) {
    if (removed[v]) continue;
    (degree[v] + 1 == left ? reduction.universal : reduction.residual).push_back(v);
  }
  return reduction;
}

Graph induced_subgraph(const Graph& graph, std::span<const std::uint32_t> vertices) {
  constexpr auto kOutside = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> index(graph.size(), kOutside);
  std::vector<double> weights;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (vertices[i] >= graph.size() || (i > 0 && vertices[i] <= vertices[i - 1]))
      throw std::invalid_argument("induced subgraph: vertices must be increasing and in the graph");
    index[vertices[i]] = static_cast<std::uint32_t>(i);
    weights.push_back(graph.weight(vertices[i]));
  }
  std::vector<Edge> edges;
  for (std::size_t i = 0; i < vertices.size(); ++i)
    for (const std::uint32_t u : graph.neighbours(vertices[i]))
      if (index[u] != kOutside && index[u] > i)
        edges.emplace_back(static_cast<std::uint32_t>(i), index[u]);
  return Graph(vertices.size(), edges, std::move(weights));
}

}  // namespace antslam::clique
