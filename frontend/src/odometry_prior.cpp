#include "antslam/frontend/odometry_prior.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cmath>
#include <stdexcept>
#include <string>

namespace antslam::frontend {

void validate(const OdometryPrior& p) {
  const auto check = [](double value, bool zero_allowed, const char* field) {
    if (!std::isfinite(value) || value < 0.0 || (!zero_allowed && value == 0.0))
      throw std::invalid_argument(std::string("odometry prior: ") + field + " must be " +
                                  (zero_allowed ? ">= 0" : "positive"));
  };
  check(p.linear, true, "linear");
  check(p.angular, true, "angular");
  check(p.drift, true, "drift");
  check(p.min_linear, false, "min_linear");
  check(p.min_angular, false, "min_angular");
}

Eigen::Matrix3d step_covariance(const OdometryPrior& p, const slam::Pose2& step) {
  const double d = std::hypot(step.x, step.y);
  const double linear = p.linear * d + p.min_linear;
  const double angular = p.angular * std::abs(step.theta) + p.drift * d + p.min_angular;
  return Eigen::Vector3d(linear * linear, linear * linear, angular * angular).asDiagonal();
}

slam::Gaussian2 fuse(const slam::Gaussian2& match, const slam::Gaussian2& prediction) {
  const Eigen::Matrix3d information = match.information() + prediction.information();
  Eigen::Matrix3d covariance = information.inverse();
  covariance = 0.5 * (covariance + covariance.transpose());
  const Eigen::Vector3d toward = prediction.mean().vector() - match.mean().vector();
  const Eigen::Vector3d wrapped(toward.x(), toward.y(), slam::wrap_angle(toward.z()));
  const Eigen::Vector3d step = covariance * (prediction.information() * wrapped);
  return {slam::Pose2::from_vector(match.mean().vector() + step), covariance};
}

bool flatter_than(const slam::Gaussian2& match, const slam::Gaussian2& prediction) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(
      match.covariance().topLeftCorner<2, 2>());
  const Eigen::Vector2d flattest = eigen.eigenvectors().col(1);  // largest eigenvalue last
  const double along = flattest.dot(prediction.covariance().topLeftCorner<2, 2>() * flattest);
  return eigen.eigenvalues()(1) > along;
}

}  // namespace antslam::frontend
