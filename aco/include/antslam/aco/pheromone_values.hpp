#pragma once
// The pheromone values of a trail, one double per trail component, and the operations that every
// trail (layered, edge, subset) shares and the pheromone-update policies call.

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

#include "antslam/aco/chunked_for.hpp"

namespace antslam::aco {

class PheromoneValues {
 public:
  std::span<const double> values() const { return tau_; }

  void fill(double value) { std::fill(tau_.begin(), tau_.end(), value); }

  /// The evaporation part of eq. (2): tau <- (1 - rho) tau.
  void evaporate(double rho, const ChunkedFor& parallel = {}) {
    const double keep = 1.0 - rho;
    parallel(tau_.size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t e = begin; e < end; ++e) tau_[e] *= keep;
    });
  }

  void clamp(double lo, double hi, const ChunkedFor& parallel = {}) {
    parallel(tau_.size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t e = begin; e < end; ++e) tau_[e] = std::clamp(tau_[e], lo, hi);
    });
  }

  double min_value() const { return *std::min_element(tau_.begin(), tau_.end()); }
  double max_value() const { return *std::max_element(tau_.begin(), tau_.end()); }

 protected:
  PheromoneValues() = default;

  /// The options of one decision whose pheromone is at least min + lambda (max - min) of theirs:
  /// its lambda-branching factor (Gambardella & Dorigo 1995).
  static double branches(std::span<const double> values, double lambda) {
    const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
    const double cutoff = *lo + lambda * (*hi - *lo);
    double count = 0.0;
    for (double t : values) count += (t >= cutoff) ? 1.0 : 0.0;
    return count;
  }
  explicit PheromoneValues(std::size_t count) : tau_(count, 0.0) {}

  std::vector<double> tau_;  // the trails index it directly in their hot loops
};

}  // namespace antslam::aco
