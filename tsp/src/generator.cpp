#include "antslam/tsp/generator.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "antslam/aco/random.hpp"

namespace antslam::tsp {

namespace {

std::uint32_t check_side(std::size_t n, double side) {
  if (n < 3) throw std::invalid_argument("a random instance needs at least 3 cities");
  if (!(side >= 1.0 && side <= kMaxCoordinateSpan))
    throw std::invalid_argument("side must be in [1, 1e9]");
  return static_cast<std::uint32_t>(std::floor(side)) + 1;  // integer coordinates 0..side
}

/// DIMACS-style name (E<n>.s<seed>, C<n>.s<seed>) and a comment saying how it was made.
Instance named(char kind, std::size_t n, std::uint64_t seed, std::vector<Point> coords,
               const std::string& how) {
  std::string name(1, kind);
  name += std::to_string(n) + ".s" + std::to_string(seed);
  Instance instance(std::move(name), EdgeWeightType::euc_2d, std::move(coords));
  instance.comment = std::to_string(n) + " cities " + how + ", seed " + std::to_string(seed) +
                     " (antslam tsp-generate)";
  return instance;
}

/// A standard normal number (Box-Muller; the second value is dropped to keep one draw order).
double normal(aco::Rng& rng) {
  const double u = 1.0 - rng.uniform();  // (0, 1]
  return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * rng.uniform());
}

}  // namespace

Instance random_uniform_instance(std::size_t n, std::uint64_t seed, double side) {
  const std::uint32_t cells = check_side(n, side);
  aco::Rng rng(aco::mix_seed(seed, 0x747370));  // "tsp": a stream of its own
  std::vector<Point> coords(n);
  for (Point& p : coords) {
    p.x = rng.below(cells);
    p.y = rng.below(cells);
  }
  return named('E', n, seed, std::move(coords),
               "uniform in [0, " + std::to_string(cells - 1) + "]^2");
}

Instance random_clustered_instance(std::size_t n, std::uint64_t seed, double side,
                                   const ClusterSettings& clusters) {
  const std::uint32_t cells = check_side(n, side);
  if (!(clusters.cities_per_cluster >= 1.0 && clusters.cities_per_cluster <= 1e9) ||
      !(clusters.spread > 0.0 && clusters.spread <= 1e6))
    throw std::invalid_argument("clusters need at least 1 city each and a positive spread");
  aco::Rng rng(aco::mix_seed(seed, 0x74737063));  // "tspc"
  const auto centres = std::max<std::size_t>(
      1, static_cast<std::size_t>(static_cast<double>(n) / clusters.cities_per_cluster));
  std::vector<Point> centre(centres);
  for (Point& c : centre) {
    c.x = rng.below(cells);
    c.y = rng.below(cells);
  }
  const double sigma = clusters.spread * side / std::sqrt(static_cast<double>(n));
  const double top = static_cast<double>(cells - 1);
  std::vector<Point> coords(n);
  for (Point& p : coords) {
    const Point& c = centre[rng.below(static_cast<std::uint32_t>(centres))];
    p.x = std::clamp(std::round(c.x + sigma * normal(rng)), 0.0, top);
    p.y = std::clamp(std::round(c.y + sigma * normal(rng)), 0.0, top);
  }
  return named('C', n, seed, std::move(coords),
               "clustered in [0, " + std::to_string(cells - 1) + "]^2 (" + std::to_string(centres) +
                   " normal clusters, spread " + std::to_string(clusters.spread) + ")");
}

}  // namespace antslam::tsp
