#pragma once
// A synthetic layered-choice problem with the shape of AntSLAM: every option of every layer has a
// unary cost in [0, 1) and a displacement; the cost adds the unary terms of the chosen options to
// a closure term that penalises the sum of the chosen displacements (like the loop-closure term
// of eq. 10, it couples all layers, so the problem is not separable). Small instances are
// solved exactly by enumeration in the tests.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include "antslam/aco/random.hpp"

namespace antslam::aco {

class SyntheticLayeredProblem {
 public:
  SyntheticLayeredProblem(std::size_t layers, std::size_t options, std::uint64_t seed)
      : layers_(layers), options_(options) {
    if (layers == 0 || options == 0) throw std::invalid_argument("empty synthetic problem");
    Rng rng(mix_seed(seed, 0x5157));
    unary_.resize(layers * options);
    displacement_.resize(layers * options);
    for (std::size_t i = 0; i < unary_.size(); ++i) {
      unary_[i] = rng.uniform();
      displacement_[i] = 2.0 * rng.uniform() - 1.0;
    }
  }

  std::size_t layer_count() const { return layers_; }
  std::size_t option_count(std::size_t) const { return options_; }

  double cost(std::span<const std::uint32_t> choice) const {
    double unary = 0.0;
    double sum = 0.0;
    for (std::size_t l = 0; l < layers_; ++l) {
      unary += unary_[l * options_ + choice[l]];
      sum += displacement_[l * options_ + choice[l]];
    }
    return unary + static_cast<double>(layers_) * (1.0 - std::exp(-sum * sum));
  }

 private:
  std::size_t layers_;
  std::size_t options_;
  std::vector<double> unary_;
  std::vector<double> displacement_;
};

}  // namespace antslam::aco
