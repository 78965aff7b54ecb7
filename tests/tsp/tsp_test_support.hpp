#pragma once
// Helpers of the TSP tests: data paths, exact optima by dynamic programming, random instances.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "../aco/test_problems.hpp"
#include "antslam/aco/random.hpp"
#include "antslam/tsp/instance.hpp"

namespace antslam::tsp::testing {

inline std::string data(const std::string& name) {
  return std::string(ANTSLAM_DATA_DIR) + "/tsplib/" + name;
}
inline std::string fixture(const std::string& name) {
  return std::string(ANTSLAM_FIXTURE_DIR) + "/" + name;
}

/// Exact optimum by Held & Karp's (1962) dynamic programme, O(2^n n^2); n <= 18.
inline double held_karp(const Instance& instance) {
  const std::size_t n = instance.size();
  const std::size_t masks = std::size_t{1} << (n - 1);  // subsets of cities 1..n-1
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<double> best(masks * (n - 1), kInf);  // best[mask][j]: path 0 .. j over mask
  const auto at = [&](std::size_t mask, std::size_t j) -> double& {
    return best[mask * (n - 1) + j];
  };
  for (std::size_t j = 0; j + 1 < n; ++j)
    at(std::size_t{1} << j, j) = instance.distance(0, static_cast<std::uint32_t>(j + 1));
  for (std::size_t mask = 1; mask < masks; ++mask)
    for (std::size_t j = 0; j + 1 < n; ++j) {
      const double here = at(mask, j);
      if (!(mask >> j & 1U) || here == kInf) continue;
      for (std::size_t k = 0; k + 1 < n; ++k) {
        if (mask >> k & 1U) continue;
        double& next = at(mask | std::size_t{1} << k, k);
        next = std::min(next, here + instance.distance(static_cast<std::uint32_t>(j + 1),
                                                       static_cast<std::uint32_t>(k + 1)));
      }
    }
  double optimum = kInf;
  for (std::size_t j = 0; j + 1 < n; ++j)
    optimum = std::min(optimum,
                       at(masks - 1, j) + instance.distance(static_cast<std::uint32_t>(j + 1), 0));
  return optimum;
}

/// n points uniform in [0, side)^2 (not rounded), of the given type.
inline Instance random_instance(std::size_t n, std::uint64_t seed, EdgeWeightType type,
                                double side = 1000.0) {
  aco::Rng rng(seed);
  std::vector<Point> points(n);
  for (Point& p : points) p = {side * rng.uniform(), side * rng.uniform()};
  return Instance("random", type, std::move(points));
}

/// Whether a tour is a permutation of 0..n-1 (the engine tests' check).
using aco::testing::is_permutation_of_n;

inline std::vector<std::uint32_t> random_tour(std::size_t n, aco::Rng& rng) {
  std::vector<std::uint32_t> tour(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = rng.below(i + 1);
    tour[i] = tour[j];
    tour[j] = i;
  }
  return tour;
}

/// The cycle `tour` with its forward path from a to b reversed (a brute-force reference for
/// the tour representations).
inline std::vector<std::uint32_t> reversed_path(std::span<const std::uint32_t> tour,
                                                std::uint32_t a, std::uint32_t b) {
  const std::size_t n = tour.size();
  const auto at = [&](std::uint32_t c) {
    return static_cast<std::size_t>(std::find(tour.begin(), tour.end(), c) - tour.begin());
  };
  const std::size_t pa = at(a), pb = at(b), length = (pb + n - pa) % n + 1;
  std::vector<std::uint32_t> out;
  for (std::size_t s = 0; s < length; ++s) out.push_back(tour[(pb + n - s) % n]);
  for (std::size_t s = length; s < n; ++s) out.push_back(tour[(pa + s) % n]);
  return out;
}

}  // namespace antslam::tsp::testing
