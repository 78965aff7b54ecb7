#pragma once
// The odometry as a prior of scan matching: a motion model gives every odometry step a
// covariance (the odometry motion model of Thrun et al., Probabilistic Robotics, Sec. 5.4: the
// error of a step grows with its length and its turn), which
//   - sizes the search window (logs whose scans are metres apart need wide windows),
//   - tells a match that contradicts the odometry (a wrong peak) from one that corrects it,
//   - and is fused with the match's Gaussian of eqs. (5)-(6) (product of the two Gaussians,
//     as a Kalman update): in a direction where the scan's likelihood is flatter than the
//     odometry's (along a featureless corridor) the odometry keeps the estimate instead of
//     letting the match slide.

#include <Eigen/Core>

#include "antslam/slamgraph/gaussian2.hpp"
#include "antslam/slamgraph/pose2.hpp"

namespace antslam::frontend {

struct OdometryPrior {
  double linear = 0.1;        ///< m/m, std of a step's translation error per metre travelled
  double angular = 0.1;       ///< rad/rad, std of a step's heading error per radian turned
  double drift = 0.02;        ///< rad/m, std of a step's heading error per metre travelled
  double min_linear = 0.02;   ///< metres, std of a step's translation error at least
  double min_angular = 0.01;  ///< radians, std of a step's heading error at least
};

/// Throws std::invalid_argument naming the first field that is negative, zero (the floors) or
/// not finite.
void validate(const OdometryPrior& prior);

/// Covariance of an odometry step (x, y, theta in the frame where the step starts): x and y
/// std linear d + min_linear, heading std angular |turn| + drift d + min_angular, d the step's
/// length; diagonal.
Eigen::Matrix3d step_covariance(const OdometryPrior& prior, const slam::Pose2& step);

/// The product of two Gaussians over the same pose, renormalised (the Kalman update of
/// `prediction` by the measurement `match`): information Omega = Omega_m + Omega_p, mean
/// mu_m + Omega^-1 Omega_p (mu_p - mu_m), angles wrapped.
slam::Gaussian2 fuse(const slam::Gaussian2& match, const slam::Gaussian2& prediction);

/// Whether the match's likelihood is flatter than the prediction in some direction of the
/// plane: the largest variance of the match's (x, y) covariance exceeds the prediction's
/// variance along the same direction (a corridor: the odometry decides along it).
bool flatter_than(const slam::Gaussian2& match, const slam::Gaussian2& prediction);

}  // namespace antslam::frontend
