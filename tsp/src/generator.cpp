#include "tsp/generator.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "aco/random.hpp"

namespace antslam::tsp {

Instance random_uniform_instance(std::size_t n, std::uint64_t seed, double side) {
  if (!(side >= 1.0 && side <= kMaxCoordinateSpan))
    throw std::invalid_argument("side must be in [1, 1e9]");
  aco::Rng rng(aco::mix_seed(seed, 0x747370));  // "tsp": a stream of its own
  const auto cells = static_cast<std::uint32_t>(std::floor(side)) + 1;
  std::vector<Point> coords(n);
  for (Point& p : coords) {
    p.x = rng.below(cells);
    p.y = rng.below(cells);
  }
  std::string name = "E";  // DIMACS-style name: E<n>.s<seed>
  name += std::to_string(n);
  name += ".s";
  name += std::to_string(seed);
  Instance instance(std::move(name), EdgeWeightType::euc_2d, std::move(coords));
  instance.comment = std::to_string(n) + " cities uniform in [0, " + std::to_string(cells - 1) +
                     "]^2, seed " + std::to_string(seed) + " (antslam tsp-generate)";
  return instance;
}

}  // namespace antslam::tsp
