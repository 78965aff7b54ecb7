#pragma once

#include <cstdint>
#include <limits>
#include <vector>

namespace antslam::aco {

/// A path built by one ant. For a permutation problem it is the tour (a permutation of the
/// cities); for a layered problem it holds one option index per layer.
struct Solution {
  std::vector<std::uint32_t> path;                        ///< the ant's choices, in order
  double cost = std::numeric_limits<double>::infinity();  ///< objective value (lower is better)
};

}  // namespace antslam::aco
