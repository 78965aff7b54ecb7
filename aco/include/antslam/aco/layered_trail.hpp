#pragma once
// Pheromone of a layered-choice problem: one value tau_lj per option j of layer l
// (AntSLAM: one value per sample of each fragment, Algorithm 2 lines 4-6).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include "antslam/aco/pheromone_values.hpp"

namespace antslam::aco {

class LayeredTrail : public PheromoneValues {
 public:
  LayeredTrail() = default;

  explicit LayeredTrail(std::span<const std::size_t> option_counts) : offset_(1, 0) {
    for (std::size_t count : option_counts) {
      if (count == 0) throw std::invalid_argument("LayeredTrail: a layer has no options");
      offset_.push_back(offset_.back() + count);
    }
    tau_.assign(offset_.back(), 0.0);
  }

  std::size_t layer_count() const { return offset_.size() - 1; }
  std::size_t option_count(std::size_t layer) const { return offset_[layer + 1] - offset_[layer]; }
  std::size_t offset(std::size_t layer) const { return offset_[layer]; }

  std::span<double> layer(std::size_t l) { return {tau_.data() + offset_[l], option_count(l)}; }
  std::span<const double> layer(std::size_t l) const {
    return {tau_.data() + offset_[l], option_count(l)};
  }
  double at(std::size_t l, std::size_t option) const { return tau_[offset_[l] + option]; }
  double& at(std::size_t l, std::size_t option) { return tau_[offset_[l] + option]; }

  // --- operations shared with the edge trail, used by the pheromone-update policies ---

  std::size_t decision_count() const { return layer_count(); }
  /// Mean number of options per decision (the "avg" of Stuetzle & Hoos's tau_min).
  double mean_options() const {
    return static_cast<double>(tau_.size()) / static_cast<double>(layer_count());
  }
  /// Branching factor of a fully converged trail.
  static constexpr double converged_branching() { return 1.0; }

  /// Calls f(tau) on the pheromone of every option the path chose.
  template <class F>
  void update_path(std::span<const std::uint32_t> path, F&& f, const ChunkedFor& parallel = {}) {
    parallel(path.size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t l = begin; l < end; ++l) f(tau_[offset_[l] + path[l]]);
    });
  }

  /// The deposit part of eq. (2) for one ant, eq. (12).
  void deposit(std::span<const std::uint32_t> path, double amount,
               const ChunkedFor& parallel = {}) {
    const auto add = [amount](double& t) { t += amount; };
    update_path(path, add, parallel);
  }

  /// Mean lambda-branching factor (Gambardella & Dorigo 1995): per layer, the number of options
  /// whose pheromone exceeds min + lambda (max - min).
  double branching_factor(double lambda) const {
    double total = 0.0;
    for (std::size_t l = 0; l < layer_count(); ++l) total += branches(layer(l), lambda);
    return total / static_cast<double>(layer_count());
  }

 private:
  std::vector<std::size_t> offset_;
};

}  // namespace antslam::aco
