#pragma once
// The pieces of Ceres pose-graph optimisation shared by the fragment-set baseline and the pose
// graph back ends: the whitened relative-pose residual and one solver run.

#include <ceres/ceres.h>

#include <Eigen/Core>
#include <cmath>
#include <numbers>
#include <vector>

#include "antslam/slamgraph/ceres_baseline.hpp"
#include "antslam/slamgraph/pose2.hpp"

namespace antslam::slam::detail {

/// U (F_a^-1 F_b A - H): the whitened residual of one edge between poses a and b, with the
/// anchor A (identity for pose-graph edges), the mean H and the upper Cholesky factor U of the
/// information matrix (U^T U = Omega, so |U r|^2 = r^T Omega r).
class RelativePoseError {
 public:
  RelativePoseError(const Pose2& anchor, const Pose2& mean, const Eigen::Matrix3d& sqrt_information)
      : anchor_(anchor), mean_(mean), sqrt_information_(sqrt_information) {}

  template <class T>
  bool operator()(const T* a, const T* b, T* residual) const {
    using std::cos, std::floor, std::sin;
    const T cb = cos(b[2]), sb = sin(b[2]);
    const T gx = b[0] + cb * anchor_.x - sb * anchor_.y;
    const T gy = b[1] + sb * anchor_.x + cb * anchor_.y;
    const T ca = cos(a[2]), sa = sin(a[2]);
    const T dx = gx - a[0], dy = gy - a[1];
    const T angle = b[2] + anchor_.theta - a[2] - mean_.theta;
    constexpr double kTwoPi = 2.0 * std::numbers::pi;
    Eigen::Matrix<T, 3, 1> r;
    r << ca * dx + sa * dy - mean_.x, -sa * dx + ca * dy - mean_.y,
        angle - kTwoPi * floor((angle + std::numbers::pi) / kTwoPi);
    Eigen::Map<Eigen::Matrix<T, 3, 1>> whitened(residual);
    whitened = sqrt_information_.cast<T>() * r;
    return true;
  }

  static ceres::CostFunction* create(const Pose2& anchor, const Pose2& mean,
                                     const Eigen::Matrix3d& sqrt_information) {
    return new ceres::AutoDiffCostFunction<RelativePoseError, 3, 3, 3>(
        new RelativePoseError(anchor, mean, sqrt_information));
  }

 private:
  Pose2 anchor_;
  Pose2 mean_;
  Eigen::Matrix3d sqrt_information_;
};

/// rho(s) = 2 (1 - exp(-s/2)): Ceres' 1/2 rho(|U r|^2) is the term 1 - N(mu, Sigma)(.) of
/// eq. (10).
class WelschLoss final : public ceres::LossFunction {
 public:
  void Evaluate(double s, double rho[3]) const override {
    const double e = std::exp(-0.5 * s);
    rho[0] = 2.0 * (1.0 - e);
    rho[1] = e;
    rho[2] = -0.5 * e;
  }
};

/// Solves `problem` over `poses` (the first one held constant by the caller) with
/// Levenberg-Marquardt and sparse normal Cholesky on one thread; the poses are updated in place.
/// Throws std::runtime_error if Ceres gives no usable solution.
CeresResult solve(ceres::Problem& problem, std::vector<Eigen::Vector3d>& poses,
                  const CeresSettings& settings);

}  // namespace antslam::slam::detail
