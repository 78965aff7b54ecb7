#pragma once
// Small problems for the engine's tests: a random Euclidean TSP (TSPLIB EUC_2D rounding),
// exhaustive search for layered problems, and a subset problem (maximum-value independent set
// of a random conflict graph) with its optimum by enumeration.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <span>
#include <utility>
#include <vector>

#include "antslam/aco/random.hpp"
#include "antslam/aco/solution.hpp"

namespace antslam::aco::testing {

class EuclideanTsp {
 public:
  EuclideanTsp(std::size_t n, std::size_t k, std::uint64_t seed)
      : EuclideanTsp(random_coordinates(n, seed), k) {}

  /// Cities at the given (x, y) points.
  EuclideanTsp(std::pair<std::vector<double>, std::vector<double>> xy, std::size_t k)
      : n_(xy.first.size()), k_(k), x_(std::move(xy.first)), y_(std::move(xy.second)) {
    const std::size_t n = n_;
    candidates_.resize(n * k);
    std::vector<std::uint32_t> order(n);
    for (std::uint32_t i = 0; i < n; ++i) {
      std::iota(order.begin(), order.end(), 0U);
      std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return distance(i, a) < distance(i, b);
      });
      std::size_t r = 0;
      for (std::uint32_t j : order)
        if (j != i && r < k) candidates_[i * k + r++] = j;
    }
  }

  static std::pair<std::vector<double>, std::vector<double>> random_coordinates(
      std::size_t n, std::uint64_t seed) {
    Rng rng(seed);
    std::pair<std::vector<double>, std::vector<double>> xy;
    for (std::size_t i = 0; i < n; ++i) {
      xy.first.push_back(1000.0 * rng.uniform());
      xy.second.push_back(1000.0 * rng.uniform());
    }
    return xy;
  }

  std::size_t size() const { return n_; }
  double distance(std::uint32_t i, std::uint32_t j) const {
    return std::floor(std::hypot(x_[i] - x_[j], y_[i] - y_[j]) + 0.5);
  }
  std::span<const std::uint32_t> candidates(std::uint32_t i) const {
    return {candidates_.data() + std::size_t{i} * k_, k_};
  }
  double cost(std::span<const std::uint32_t> tour) const {
    double total = 0.0;
    for (std::size_t s = 0; s < tour.size(); ++s)
      total += distance(tour[s], tour[(s + 1) % tour.size()]);
    return total;
  }

 private:
  std::size_t n_;
  std::size_t k_;
  std::vector<double> x_, y_;
  std::vector<std::uint32_t> candidates_;
};

inline bool is_permutation_of_n(std::span<const std::uint32_t> tour, std::size_t n) {
  if (tour.size() != n) return false;
  std::vector<bool> seen(n, false);
  for (std::uint32_t c : tour) {
    if (c >= n || seen[c]) return false;
    seen[c] = true;
  }
  return true;
}

/// The optimum of a layered problem by enumerating every choice.
template <class P>
Solution exhaustive_optimum(const P& problem) {
  const std::size_t layers = problem.layer_count();
  std::vector<std::uint32_t> choice(layers, 0);
  Solution best;
  for (;;) {
    const double c = problem.cost(choice);
    if (c < best.cost) best = Solution{choice, c};
    std::size_t l = 0;
    while (l < layers && ++choice[l] == problem.option_count(l)) choice[l++] = 0;
    if (l == layers) return best;
  }
}

/// Maximum-value independent set as a subset problem: n elements with values in [1, 2), random
/// conflicts with probability p; compatible = not in conflict; cost = 1 + value left out.
class ConflictSubsetProblem {
 public:
  ConflictSubsetProblem(std::size_t n, double p, std::uint64_t seed) : n_(n), conflict_(n * n) {
    Rng rng(mix_seed(seed, 0x5B5E7));
    for (std::size_t i = 0; i < n; ++i) {
      value_.push_back(1.0 + rng.uniform());
      total_ += value_.back();
      for (std::size_t j = 0; j < i; ++j)
        conflict_[i * n + j] = conflict_[j * n + i] = rng.uniform() < p ? 1 : 0;
    }
  }

  std::size_t element_count() const { return n_; }
  bool compatible(std::uint32_t i, std::uint32_t j) const {
    return conflict_[std::size_t{i} * n_ + j] == 0;
  }
  double cost(std::span<const std::uint32_t> set) const {
    double chosen = 0.0;
    for (std::uint32_t e : set) chosen += value_[e];
    return 1.0 + total_ - chosen;
  }

  /// Whether `set` has distinct elements, no conflict, and no element that could be added.
  bool maximal_independent(std::span<const std::uint32_t> set) const {
    std::vector<bool> in(n_, false);
    for (std::uint32_t e : set) {
      if (e >= n_ || in[e]) return false;
      in[e] = true;
    }
    for (std::uint32_t e = 0; e < n_; ++e) {
      bool addable = !in[e];
      for (std::uint32_t f : set) {
        if (f != e && !compatible(e, f) && in[e]) return false;
        addable = addable && compatible(e, f);
      }
      if (addable) return false;
    }
    return true;
  }

  /// The least cost over all independent sets (n <= 20).
  double optimum() const {
    double best = std::numeric_limits<double>::infinity();
    std::vector<std::uint32_t> set;
    for (std::uint32_t mask = 0; mask < (1U << n_); ++mask) {
      set.clear();
      bool independent = true;
      for (std::uint32_t e = 0; e < n_ && independent; ++e) {
        if (((mask >> e) & 1U) == 0) continue;
        for (std::uint32_t f : set) independent = independent && compatible(e, f);
        set.push_back(e);
      }
      if (independent) best = std::min(best, cost(set));
    }
    return best;
  }

 private:
  std::size_t n_;
  std::vector<double> value_;
  std::vector<std::uint8_t> conflict_;
  double total_ = 0.0;
};

}  // namespace antslam::aco::testing
