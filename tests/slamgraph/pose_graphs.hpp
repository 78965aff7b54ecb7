#pragma once
// Pose graphs with known truth for the consistency and robust back-end tests: a robot drives
// laps of a square; odometry and loop closures between the same corner of different laps are
// measured from the true poses with Gaussian noise drawn from their stated covariances.

#include <Eigen/LU>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <vector>

#include "antslam/aco/random.hpp"
#include "antslam/slamgraph/g2o.hpp"
#include "support.hpp"

namespace antslam::slam::testing {

struct TrueGraph {
  PoseGraph graph;
  std::vector<Pose2> truth;
};

/// `laps` laps of a square of `side` 1 m steps; closures every `closure_every`-th pose of a lap to
/// the same pose of every later lap; odometry and closures with random correlated covariances of
/// scale `scale` and noise drawn from them scaled by `noise` (1: as stated; < 1: the stated
/// covariances are conservative, as in many public graphs). Noise-free measurements with unit
/// covariances for scale = 0.
inline TrueGraph square_laps(std::size_t laps, std::size_t side, std::size_t closure_every,
                             double scale, std::uint64_t seed, double noise = 1.0) {
  aco::Rng rng(aco::mix_seed(seed, 0x5A0));
  TrueGraph t;
  const std::size_t lap = 4 * side;
  Pose2 p;
  for (std::size_t i = 0; i < laps * lap; ++i) {
    t.truth.push_back(p);
    const bool corner = (i + 1) % side == 0;
    p = p * Pose2{1.0, 0.0, corner ? 0.5 * std::numbers::pi : 0.0};
  }
  t.graph.vertices = t.truth;
  const auto measure = [&](std::size_t i, std::size_t j) {
    const Eigen::Matrix3d covariance =
        scale > 0.0 ? random_covariance(rng, scale) : Eigen::Matrix3d::Identity().eval();
    Pose2 z = between(t.truth[i], t.truth[j]);
    if (scale > 0.0)
      z = z * Pose2::from_vector(noise * Gaussian2(Pose2{}, covariance).sample(rng).vector());
    t.graph.edges.push_back({i, j, z, covariance.inverse()});
  };
  for (std::size_t i = 0; i + 1 < t.truth.size(); ++i) measure(i, i + 1);
  for (std::size_t i = 0; i < t.truth.size(); i += closure_every)
    for (std::size_t j = i + lap; j < t.truth.size(); j += lap) measure(j, i);
  return t;
}

}  // namespace antslam::slam::testing
