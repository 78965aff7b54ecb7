#pragma once
// Wheel odometry made from a known path: each step's true motion u_i = p_{i-1}^-1 p_i gets
// zero-mean Gaussian errors whose spread grows with the step (the odometry motion model of
// Thrun et al., Probabilistic Robotics, Sec. 5.4) plus a systematic heading bias per metre (an
// uneven wheel), and the noisy steps are composed from the first pose. The simulator drives its
// robots with it; `antslam simulate-odometry` turns corrected logs into benchmarks with it.

#include <span>
#include <vector>

#include "antslam/aco/random.hpp"
#include "antslam/slamgraph/pose2.hpp"

namespace antslam::frontend {

struct OdometryNoise {
  double linear = 0.05;         ///< std of translation error per metre of the step (m/m)
  double angular = 0.05;        ///< std of heading error per radian turned in the step (rad/rad)
  double drift = 0.01;          ///< std of heading error per metre of the step (rad/m)
  double heading_bias = 0.002;  ///< systematic heading error per metre travelled (rad/m)
};

/// Throws std::invalid_argument naming the first field that is negative or not finite.
void validate(const OdometryNoise& noise);

/// The odometry along `path`: o_0 = p_0, o_i = o_{i-1} (+) (u_i + e_i) with, for a step of
/// length d and turn a, e_i = (N(0, (linear d)^2), N(0, (linear d / 2)^2),
/// N(0, (angular |a| + drift d)^2) + heading_bias d). Three normal draws per step from `rng`.
/// With zero noise the odometry is the path (up to rounding).
std::vector<slam::Pose2> noisy_odometry(std::span<const slam::Pose2> path,
                                        const OdometryNoise& noise, aco::Rng& rng);

}  // namespace antslam::frontend
