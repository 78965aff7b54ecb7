#pragma once
// A Gaussian over a pose (x, y, theta): the alignment distributions of eqs. (5)-(7) and the
// loop-closure distribution N(mu_H, Sigma_H).
//
// Reading of eq. (10): "N(mu, Sigma)(E)" is taken as the peak-normalised density
//   value(E) = exp(-0.5 r^T Sigma^-1 r),  r = E - mu with the angle wrapped,
// so each term 1 - value(E) lies in [0, 1] and a perfect fit costs 0. (The normalised density
// would make the weight depend on the determinant of Sigma and could be negative.)

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "antslam/aco/random.hpp"
#include "antslam/slamgraph/pose2.hpp"

namespace antslam::slam {

/// A standard normal draw from two uniforms (Box-Muller), identical on every platform.
double standard_normal(aco::Rng& rng);

class Gaussian2 {
 public:
  /// Unit covariance at the origin.
  Gaussian2();
  /// Throws std::invalid_argument naming the problem if the covariance is not finite,
  /// symmetric and positive definite, or the mean is not finite.
  Gaussian2(const Pose2& mean, const Eigen::Matrix3d& covariance);

  const Pose2& mean() const { return mean_; }
  const Eigen::Matrix3d& covariance() const { return covariance_; }
  /// Omega = Sigma^-1.
  const Eigen::Matrix3d& information() const { return information_; }
  /// Lower Cholesky factor L of Sigma (Sigma = L L^T), used for sampling.
  const Eigen::Matrix3d& covariance_factor() const { return covariance_factor_; }
  /// Upper Cholesky factor U of Omega (U^T U = Omega): whitens residuals, |U r|^2 = r^T Omega r.
  const Eigen::Matrix3d& information_factor() const { return information_factor_; }

  /// r = p - mu, angle wrapped.
  Eigen::Vector3d residual(const Pose2& p) const;
  /// r^T Sigma^-1 r.
  double mahalanobis_squared(const Pose2& p) const;
  /// exp(-0.5 r^T Sigma^-1 r) in (0, 1]: the value used in eq. (10).
  double value(const Pose2& p) const;
  /// A draw s ~ N(mu, Sigma), eq. (7).
  Pose2 sample(aco::Rng& rng) const;

 private:
  Pose2 mean_;
  Eigen::Matrix3d covariance_;
  Eigen::Matrix3d information_;
  Eigen::Matrix3d covariance_factor_;
  Eigen::Matrix3d information_factor_;
};

}  // namespace antslam::slam
