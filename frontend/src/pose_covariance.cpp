#include "antslam/frontend/pose_covariance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace antslam::frontend {

slam::Gaussian2 moment_match(std::span<const WeightedPose> candidates,
                             const Eigen::Matrix3d& floor) {
  if (candidates.empty()) throw std::invalid_argument("moment_match: no candidates");
  double top = -std::numeric_limits<double>::infinity();
  for (const WeightedPose& c : candidates) top = std::max(top, c.log_weight);
  if (!std::isfinite(top)) throw std::invalid_argument("moment_match: no finite weight");
  // Eq. (5), with the circular mean for the heading.
  double total = 0.0, x = 0.0, y = 0.0, s = 0.0, c = 0.0;
  for (const WeightedPose& k : candidates) {
    const double p = std::exp(k.log_weight - top);
    total += p;
    x += p * k.pose.x;
    y += p * k.pose.y;
    s += p * std::sin(k.pose.theta);
    c += p * std::cos(k.pose.theta);
  }
  const slam::Pose2 mean{x / total, y / total, std::atan2(s, c)};
  // Eq. (6).
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const WeightedPose& k : candidates) {
    const double p = std::exp(k.log_weight - top) / total;
    const Eigen::Vector3d r(k.pose.x - mean.x, k.pose.y - mean.y,
                            slam::wrap_angle(k.pose.theta - mean.theta));
    covariance.noalias() += p * r * r.transpose();
  }
  return {mean, covariance + floor};
}

namespace {

/// d(a * b) / da and d(a * b) / db.
void composition_jacobians(const slam::Pose2& a, const slam::Pose2& b, Eigen::Matrix3d& ja,
                           Eigen::Matrix3d& jb) {
  const double c = std::cos(a.theta), s = std::sin(a.theta);
  ja << 1.0, 0.0, -s * b.x - c * b.y,  //
      0.0, 1.0, c * b.x - s * b.y,     //
      0.0, 0.0, 1.0;
  jb << c, -s, 0.0,  //
      s, c, 0.0,     //
      0.0, 0.0, 1.0;
}

}  // namespace

Eigen::Matrix3d compose_covariance(const slam::Pose2& a, const Eigen::Matrix3d& cov_a,
                                   const slam::Pose2& b, const Eigen::Matrix3d& cov_b) {
  Eigen::Matrix3d ja, jb;
  composition_jacobians(a, b, ja, jb);
  const Eigen::Matrix3d out = ja * cov_a * ja.transpose() + jb * cov_b * jb.transpose();
  return 0.5 * (out + out.transpose());
}

Eigen::Matrix3d inverse_covariance(const slam::Pose2& a, const Eigen::Matrix3d& cov_a) {
  // a^-1 = (-R^T t, -theta): d/dt = -R^T, d/dtheta = (s tx - c ty, c tx + s ty), -1.
  const double c = std::cos(a.theta), s = std::sin(a.theta);
  Eigen::Matrix3d j;
  j << -c, -s, s * a.x - c * a.y,  //
      s, -c, c * a.x + s * a.y,    //
      0.0, 0.0, -1.0;
  const Eigen::Matrix3d out = j * cov_a * j.transpose();
  return 0.5 * (out + out.transpose());
}

}  // namespace antslam::frontend
