#pragma once
// SE(2) poses: (x, y, theta) with composition, inverse and angle wrapping.

#include <Eigen/Core>
#include <cmath>
#include <numbers>

namespace antslam::slam {

/// Angle wrapped into [-pi, pi).
inline double wrap_angle(double a) {
  a = std::fmod(a + std::numbers::pi, 2.0 * std::numbers::pi);
  if (a < 0.0) a += 2.0 * std::numbers::pi;
  return a - std::numbers::pi;
}

struct Pose2 {
  double x = 0.0;      ///< metres
  double y = 0.0;      ///< metres
  double theta = 0.0;  ///< radians, kept in [-pi, pi)

  static Pose2 from_vector(const Eigen::Vector3d& v) { return {v.x(), v.y(), wrap_angle(v.z())}; }
  Eigen::Vector3d vector() const { return {x, y, theta}; }
  Eigen::Vector2d translation() const { return {x, y}; }

  /// Composition this * b: b expressed in this pose's frame, moved to the parent frame.
  Pose2 operator*(const Pose2& b) const {
    const double c = std::cos(theta), s = std::sin(theta);
    return {x + c * b.x - s * b.y, y + s * b.x + c * b.y, wrap_angle(theta + b.theta)};
  }

  /// A point of this pose's frame, in the parent frame.
  Eigen::Vector2d operator*(const Eigen::Vector2d& p) const {
    const double c = std::cos(theta), s = std::sin(theta);
    return {x + c * p.x() - s * p.y(), y + s * p.x() + c * p.y()};
  }

  Pose2 inverse() const {
    const double c = std::cos(theta), s = std::sin(theta);
    return {-c * x - s * y, s * x - c * y, wrap_angle(-theta)};
  }
};

/// The pose of b in a's frame: a^-1 * b.
inline Pose2 between(const Pose2& a, const Pose2& b) { return a.inverse() * b; }

}  // namespace antslam::slam
