#pragma once
// Gaussians over poses: moment matching of weighted candidate poses (paper eqs. 5-6, as in
// GMapping's improved proposal) and first-order propagation through pose composition.

#include <Eigen/Core>
#include <span>

#include "antslam/slamgraph/gaussian2.hpp"
#include "antslam/slamgraph/pose2.hpp"

namespace antslam::frontend {

struct WeightedPose {
  slam::Pose2 pose;         ///< a candidate pose x_k
  double log_weight = 0.0;  ///< log p(z | m, x), up to a constant
};

/// Eqs. (5)-(6): mu = eta sum_k x_k p_k and Sigma = eta sum_k (x_k - mu)(x_k - mu)^T p_k with
/// p_k = exp(log_weight_k - max) and eta = 1 / sum_k p_k; the heading of mu is the circular
/// mean atan2(sum p_k sin theta_k, sum p_k cos theta_k) and residuals wrap. `floor` is added to
/// Sigma: the spread of each candidate's own cell (h^2 / 12 per axis for a lattice of spacing h),
/// which keeps Sigma positive definite when one candidate takes all the weight.
slam::Gaussian2 moment_match(std::span<const WeightedPose> candidates,
                             const Eigen::Matrix3d& floor);

/// Covariance of a * b (slam::Pose2 composition) for independent a ~ (a, cov_a), b ~ (b, cov_b),
/// to first order: J_a cov_a J_a^T + J_b cov_b J_b^T.
Eigen::Matrix3d compose_covariance(const slam::Pose2& a, const Eigen::Matrix3d& cov_a,
                                   const slam::Pose2& b, const Eigen::Matrix3d& cov_b);

/// Covariance of a^-1 for a ~ (a, cov_a), to first order.
Eigen::Matrix3d inverse_covariance(const slam::Pose2& a, const Eigen::Matrix3d& cov_a);

}  // namespace antslam::frontend
