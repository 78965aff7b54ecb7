#include "antslam/eval/alignment.hpp"

#include <cmath>
#include <stdexcept>

namespace antslam::eval {

slam::Pose2 align(std::span<const PosePair> pairs) {
  if (pairs.empty()) throw std::invalid_argument("align: no associated poses");
  Eigen::Vector2d mu_e = Eigen::Vector2d::Zero(), mu_r = Eigen::Vector2d::Zero();
  for (const PosePair& p : pairs) {
    mu_e += p.estimate.translation();
    mu_r += p.reference.translation();
  }
  mu_e /= static_cast<double>(pairs.size());
  mu_r /= static_cast<double>(pairs.size());
  double dot = 0.0, cross = 0.0;
  for (const PosePair& p : pairs) {
    const Eigen::Vector2d a = p.estimate.translation() - mu_e;
    const Eigen::Vector2d b = p.reference.translation() - mu_r;
    dot += a.dot(b);
    cross += a.x() * b.y() - a.y() * b.x();
  }
  const double alpha = std::atan2(cross, dot);  // atan2(0, 0) = 0 when all e_i coincide
  const slam::Pose2 rotation{0.0, 0.0, alpha};
  const Eigen::Vector2d t = mu_r - (rotation * mu_e);
  return {t.x(), t.y(), slam::wrap_angle(alpha)};
}

double alignment_cost(std::span<const PosePair> pairs, const slam::Pose2& transform) {
  double cost = 0.0;
  for (const PosePair& p : pairs)
    cost += (transform * p.estimate.translation() - p.reference.translation()).squaredNorm();
  return cost;
}

slam::Trajectory transformed(const slam::Trajectory& trajectory, const slam::Pose2& transform) {
  slam::Trajectory out = trajectory;
  for (slam::StampedPose& p : out) p.pose = transform * p.pose;
  return out;
}

}  // namespace antslam::eval
