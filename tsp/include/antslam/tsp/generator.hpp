#pragma once
// Random instances, EUC_2D, integer coordinates in [0, side]^2; same seed, same instance. Two
// kinds, as the DIMACS TSP Challenge's generators (Johnson & McGeoch 2002, portgen/portcgen):
//   uniform    cities uniform in the square ("E" instances, side 1e6);
//   clustered  n/10 centres uniform in the square, each city a centre (uniformly chosen) plus a
//              normal offset of standard deviation side/sqrt(n) per coordinate ("C"
//              instances), clamped to the square; ClusterSettings tighten or widen them.

#include <cstddef>
#include <cstdint>

#include "antslam/tsp/instance.hpp"

namespace antslam::tsp {

/// Throws std::invalid_argument if n < 3 or side is not in [1, kMaxCoordinateSpan].
Instance random_uniform_instance(std::size_t n, std::uint64_t seed, double side = 1.0e6);
struct ClusterSettings {
  double cities_per_cluster = 10.0;  ///< n / this many centres (at least one); DIMACS: 10
  double spread = 1.0;               ///< standard deviation in units of side/sqrt(n); DIMACS: 1
};

/// The clustered kind; the same errors, and std::invalid_argument for settings that are not
/// positive and finite.
Instance random_clustered_instance(std::size_t n, std::uint64_t seed, double side = 1.0e6,
                                   const ClusterSettings& clusters = {});

}  // namespace antslam::tsp
