#pragma once
// An undirected simple graph on the vertices 0..n-1 with a positive weight per vertex, kept both
// as sorted adjacency lists and as an adjacency bit matrix (n^2 / 8 bytes: 1.1 MB for 3,000
// vertices), so that an adjacency test is one load and a neighbourhood intersection is a word-wise
// AND (the bit-parallel representation of San Segundo et al. 2011).

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace antslam::clique {

using Edge = std::pair<std::uint32_t, std::uint32_t>;

class Graph {
 public:
  /// Throws std::invalid_argument for an edge to itself or to a vertex >= vertices, and for a
  /// weight that is not finite and positive; an empty `weights` means weight 1 for every vertex.
  /// Repeated edges are kept once.
  Graph(std::size_t vertices, std::span<const Edge> edges, std::vector<double> weights = {});

  std::size_t size() const { return n_; }
  std::size_t edge_count() const { return edge_count_; }
  /// 64-bit words of one bit-matrix row.
  std::size_t words() const { return words_; }

  bool adjacent(std::uint32_t i, std::uint32_t j) const {
    return ((bits_[std::size_t{i} * words_ + (j >> 6U)] >> (j & 63U)) & 1U) != 0;
  }
  /// Bit j of row(i) is set when i and j are adjacent.
  std::span<const std::uint64_t> row(std::uint32_t i) const {
    return {bits_.data() + std::size_t{i} * words_, words_};
  }
  /// The neighbours of i, increasing.
  std::span<const std::uint32_t> neighbours(std::uint32_t i) const {
    return {neighbour_.data() + offset_[i], offset_[i + 1] - offset_[i]};
  }
  std::size_t degree(std::uint32_t i) const { return offset_[i + 1] - offset_[i]; }

  double weight(std::uint32_t i) const { return weight_[i]; }
  std::span<const double> weights() const { return weight_; }
  double total_weight() const { return total_weight_; }
  /// Every vertex has weight 1 (maximum clique by cardinality).
  bool unit_weights() const { return unit_weights_; }

 private:
  std::size_t n_ = 0;
  std::size_t words_ = 0;
  std::size_t edge_count_ = 0;
  std::vector<std::uint64_t> bits_;
  std::vector<std::size_t> offset_;
  std::vector<std::uint32_t> neighbour_;
  std::vector<double> weight_;
  double total_weight_ = 0.0;
  bool unit_weights_ = true;
};

/// Whether the vertices are distinct and pairwise adjacent.
bool is_clique(const Graph& graph, std::span<const std::uint32_t> vertices);
/// Whether no vertex outside the clique is adjacent to all of it.
bool is_maximal_clique(const Graph& graph, std::span<const std::uint32_t> vertices);
/// Sum of the vertices' weights.
double weight_of(const Graph& graph, std::span<const std::uint32_t> vertices);

/// A clique found by one of the searches.
struct CliqueResult {
  std::vector<std::uint32_t> vertices;  ///< the clique, increasing
  double weight = 0.0;                  ///< its weight (its size for unit weights)
  double upper_bound = 0.0;             ///< no clique weighs more (proven bound)
  bool optimal = false;                 ///< weight == upper_bound: proven maximum
  double elapsed_s = 0.0;               ///< wall-clock seconds of the search
};

}  // namespace antslam::clique
