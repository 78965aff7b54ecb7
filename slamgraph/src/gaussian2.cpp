#include "antslam/slamgraph/gaussian2.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace antslam::slam {

double standard_normal(aco::Rng& rng) {
  const double u1 = 1.0 - rng.uniform();  // (0, 1]
  const double u2 = rng.uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

Gaussian2::Gaussian2() : Gaussian2(Pose2{}, Eigen::Matrix3d::Identity()) {}

Gaussian2::Gaussian2(const Pose2& mean, const Eigen::Matrix3d& covariance)
    : mean_(mean), covariance_(covariance) {
  if (!std::isfinite(mean.x) || !std::isfinite(mean.y) || !std::isfinite(mean.theta))
    throw std::invalid_argument("mean is not finite");
  if (!covariance.allFinite()) throw std::invalid_argument("covariance is not finite");
  const double scale = covariance.cwiseAbs().maxCoeff();
  if ((covariance - covariance.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale)
    throw std::invalid_argument("covariance is not symmetric");
  const Eigen::LLT<Eigen::Matrix3d> llt(covariance);
  if (llt.info() != Eigen::Success || !(llt.matrixL().toDenseMatrix().diagonal().minCoeff() > 0.0))
    throw std::invalid_argument("covariance is not positive definite");
  covariance_factor_ = llt.matrixL();
  information_ = llt.solve(Eigen::Matrix3d::Identity());
  information_ = 0.5 * (information_ + information_.transpose()).eval();
  const Eigen::LLT<Eigen::Matrix3d> info_llt(information_);
  if (info_llt.info() != Eigen::Success)
    throw std::invalid_argument("covariance is too ill-conditioned to invert");
  information_factor_ = info_llt.matrixU();
}

Eigen::Vector3d Gaussian2::residual(const Pose2& p) const {
  return {p.x - mean_.x, p.y - mean_.y, wrap_angle(p.theta - mean_.theta)};
}

double Gaussian2::mahalanobis_squared(const Pose2& p) const {
  const Eigen::Vector3d r = residual(p);
  return r.dot(information_ * r);
}

double Gaussian2::value(const Pose2& p) const { return std::exp(-0.5 * mahalanobis_squared(p)); }

Pose2 Gaussian2::sample(aco::Rng& rng) const {
  Eigen::Vector3d z;
  for (int k = 0; k < 3; ++k) z[k] = standard_normal(rng);
  const Eigen::Vector3d d = covariance_factor_ * z;
  return {mean_.x + d.x(), mean_.y + d.y(), wrap_angle(mean_.theta + d.z())};
}

}  // namespace antslam::slam
