#pragma once
// Pheromone of a subset-selection problem: one value tau_e per element e, the "vertex" pheromone
// of Solnon & Fenet's Ant-Clique (2006): the desirability of taking e into the set.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include "antslam/aco/pheromone_values.hpp"

namespace antslam::aco {

class SubsetTrail : public PheromoneValues {
 public:
  SubsetTrail() = default;

  explicit SubsetTrail(std::size_t elements) : PheromoneValues(elements) {
    if (elements == 0) throw std::invalid_argument("SubsetTrail: no elements");
  }

  std::size_t element_count() const { return tau_.size(); }
  double at(std::size_t element) const { return tau_[element]; }

  // --- operations shared with the other trails, used by the pheromone-update policies ---

  /// Every element is one decision: in the set or not.
  std::size_t decision_count() const { return tau_.size(); }
  /// Two options (in, out) per decision (the "avg" of Stuetzle & Hoos's tau_min).
  static constexpr double mean_options() { return 2.0; }
  /// Branching factor of a fully converged trail (see branching_factor).
  static constexpr double converged_branching() { return 1.0; }

  /// Calls f(tau) on the pheromone of every element of the set.
  template <class F>
  void update_path(std::span<const std::uint32_t> subset, F&& f, const ChunkedFor& parallel = {}) {
    parallel(subset.size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t k = begin; k < end; ++k) f(tau_[subset[k]]);
    });
  }

  /// The deposit part of eq. (2) for one ant.
  void deposit(std::span<const std::uint32_t> subset, double amount,
               const ChunkedFor& parallel = {}) {
    const auto add = [amount](double& t) { t += amount; };
    update_path(subset, add, parallel);
  }

  /// The lambda-branching factor (Gambardella & Dorigo 1995) of two-option decisions: an element
  /// whose pheromone lies within lambda (max - min) of the minimum or of the maximum has one
  /// strong option (left out, or taken), any other element two. The mean over elements is 1
  /// exactly when the colony has decided every element.
  double branching_factor(double lambda) const {
    const auto [lo, hi] = std::minmax_element(tau_.begin(), tau_.end());
    const double low_cut = *lo + lambda * (*hi - *lo);
    const double high_cut = *hi - lambda * (*hi - *lo);
    double undecided = 0.0;
    for (double t : tau_) undecided += (t > low_cut && t < high_cut) ? 1.0 : 0.0;
    return 1.0 + undecided / static_cast<double>(tau_.size());
  }
};

}  // namespace antslam::aco
