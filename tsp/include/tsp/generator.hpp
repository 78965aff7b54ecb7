#pragma once
// Random instances: n cities with integer coordinates drawn uniformly from [0, side]^2 (the
// DIMACS TSP Challenge's "E" instances use side = 1e6), EUC_2D. Same seed, same instance.

#include <cstddef>
#include <cstdint>

#include "tsp/instance.hpp"

namespace antslam::tsp {

/// Throws std::invalid_argument if n < 3 or side is not in [1, kMaxCoordinateSpan].
Instance random_uniform_instance(std::size_t n, std::uint64_t seed, double side = 1.0e6);

}  // namespace antslam::tsp
