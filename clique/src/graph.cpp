#include "antslam/clique/graph.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <new>
#include <stdexcept>
#include <string>

#include "bits.hpp"

namespace antslam::clique {

Graph::Graph(std::size_t vertices, std::span<const Edge> edges, std::vector<double> weights)
    : n_(vertices), words_(detail::word_count(vertices)), weight_(std::move(weights)) {
  if (n_ > std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("clique graph: " + std::to_string(n_) +
                            " vertices (at most 4294967295)");
  // n^2 bits: a million vertices need 125 GB.
  const auto too_large = [&] {
    const double megabytes = static_cast<double>(n_) * static_cast<double>(words_) * 8e-6;
    return std::length_error("clique graph: the adjacency bits of " + std::to_string(n_) +
                             " vertices (" + std::to_string(std::llround(megabytes)) +
                             " MB) do not fit in memory");
  };
  if (words_ != 0 && n_ > bits_.max_size() / words_) throw too_large();
  try {
    bits_.assign(n_ * words_, 0);
  } catch (const std::bad_alloc&) {
    throw too_large();
  }
  if (weight_.empty()) weight_.assign(n_, 1.0);
  if (weight_.size() != n_)
    throw std::invalid_argument("clique graph: " + std::to_string(weight_.size()) +
                                " weights for " + std::to_string(n_) + " vertices");
  for (std::size_t v = 0; v < n_; ++v) {
    if (!std::isfinite(weight_[v]) || !(weight_[v] > 0.0))
      throw std::invalid_argument("clique graph: weight of vertex " + std::to_string(v) +
                                  " is not a finite positive number");
    total_weight_ += weight_[v];
    unit_weights_ = unit_weights_ && weight_[v] == 1.0;
  }
  for (const auto& [i, j] : edges) {
    if (i >= n_ || j >= n_)
      throw std::invalid_argument("clique graph: edge " + std::to_string(i) + "-" +
                                  std::to_string(j) + " names a vertex >= " + std::to_string(n_));
    if (i == j)
      throw std::invalid_argument("clique graph: edge from vertex " + std::to_string(i) +
                                  " to itself");
    detail::set_bit({bits_.data() + std::size_t{i} * words_, words_}, j);
    detail::set_bit({bits_.data() + std::size_t{j} * words_, words_}, i);
  }
  offset_.assign(n_ + 1, 0);
  neighbour_.reserve(2 * edges.size());  // exact unless edges repeat
  for (std::uint32_t v = 0; v < n_; ++v) {
    detail::for_each_bit(row(v), [&](std::uint32_t u) { neighbour_.push_back(u); });
    offset_[v + 1] = neighbour_.size();
  }
  edge_count_ = neighbour_.size() / 2;
}

bool is_clique(const Graph& graph, std::span<const std::uint32_t> vertices) {
  for (std::size_t a = 0; a < vertices.size(); ++a) {
    if (vertices[a] >= graph.size()) return false;
    for (std::size_t b = 0; b < a; ++b)
      if (!graph.adjacent(vertices[a], vertices[b])) return false;
  }
  return true;
}

bool is_maximal_clique(const Graph& graph, std::span<const std::uint32_t> vertices) {
  if (!is_clique(graph, vertices)) return false;
  for (std::uint32_t v = 0; v < graph.size(); ++v)
    if (std::all_of(vertices.begin(), vertices.end(),
                    [&](std::uint32_t u) { return graph.adjacent(u, v); }))
      return false;
  return true;
}

double weight_of(const Graph& graph, std::span<const std::uint32_t> vertices) {
  double total = 0.0;
  for (const std::uint32_t v : vertices) total += graph.weight(v);
  return total;
}

}  // namespace antslam::clique
