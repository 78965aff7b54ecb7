#pragma once
// The graph renumbered by non-increasing degree (ties by vertex), so that the bit order of the
// candidate sets is the colouring order of MCQ, and the greedy colouring of a candidate set.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <span>
#include <vector>

#include "antslam/clique/graph.hpp"
#include "bits.hpp"

namespace antslam::clique::detail {

class RenumberedGraph {
 public:
  explicit RenumberedGraph(const Graph& graph)
      : n_(graph.size()), words_(graph.words()), original_(graph.size()) {
    std::iota(original_.begin(), original_.end(), 0U);
    std::stable_sort(original_.begin(), original_.end(), [&](std::uint32_t a, std::uint32_t b) {
      return graph.degree(a) > graph.degree(b);
    });
    std::vector<std::uint32_t> renumbered(n_);
    for (std::uint32_t v = 0; v < n_; ++v) renumbered[original_[v]] = v;
    bits_.assign(n_ * words_, 0);
    weight_.resize(n_);
    for (std::uint32_t v = 0; v < n_; ++v) {
      weight_[v] = graph.weight(original_[v]);
      const std::span<std::uint64_t> bits{bits_.data() + std::size_t{v} * words_, words_};
      for (const std::uint32_t u : graph.neighbours(original_[v])) set_bit(bits, renumbered[u]);
    }
  }

  std::size_t size() const { return n_; }
  std::size_t words() const { return words_; }
  std::span<const std::uint64_t> row(std::uint32_t v) const {
    return {bits_.data() + std::size_t{v} * words_, words_};
  }
  double weight(std::uint32_t v) const { return weight_[v]; }
  std::uint32_t original(std::uint32_t v) const { return original_[v]; }

 private:
  std::size_t n_;
  std::size_t words_;
  std::vector<std::uint32_t> original_;  // renumbered vertex -> vertex of the graph
  std::vector<std::uint64_t> bits_;
  std::vector<double> weight_;
};

/// Greedy colouring of `candidates` in bit order: each class takes, in order, every remaining
/// candidate adjacent to none of the class. `order` receives the candidates class by class,
/// `bound[i]` the sum of the heaviest weights of the classes up to order[i]'s (an upper bound on
/// a clique among order[0..i]). `remaining` and `open` are scratch sets of the graph's width.
inline void colour(const RenumberedGraph& g, std::span<const std::uint64_t> candidates,
                   Bits& remaining, Bits& open, std::vector<std::uint32_t>& order,
                   std::vector<double>& bound) {
  remaining.assign(candidates.begin(), candidates.end());
  open.resize(remaining.size());
  order.clear();
  bound.clear();
  double total = 0.0;
  while (any(remaining)) {
    open = remaining;
    double heaviest = 0.0;
    for (std::size_t k = 0; k < open.size(); ++k) {
      while (open[k] != 0) {
        const auto v = static_cast<std::uint32_t>(
            k * 64 + static_cast<std::size_t>(std::countr_zero(open[k])));
        clear_bit(remaining, v);
        order.push_back(v);
        heaviest = std::max(heaviest, g.weight(v));
        const auto row = g.row(v);
        for (std::size_t j = k; j < open.size(); ++j) open[j] &= ~row[j];
        clear_bit(open, v);
      }
    }
    total += heaviest;
    bound.resize(order.size(), total);  // the class just built
  }
}

}  // namespace antslam::clique::detail
