#pragma once
// Small problems for the engine's tests: a random Euclidean TSP (TSPLIB EUC_2D rounding) and
// exhaustive search for layered problems.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <span>
#include <vector>

#include "aco/random.hpp"
#include "aco/solution.hpp"

namespace antslam::aco::testing {

class EuclideanTsp {
 public:
  EuclideanTsp(std::size_t n, std::size_t k, std::uint64_t seed) : n_(n), k_(k) {
    Rng rng(seed);
    x_.resize(n);
    y_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      x_[i] = 1000.0 * rng.uniform();
      y_[i] = 1000.0 * rng.uniform();
    }
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

}  // namespace antslam::aco::testing
