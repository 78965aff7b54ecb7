#include "antslam/frontend/pose_likelihood.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <vector>

#include "antslam/frontend/pose_covariance.hpp"

namespace antslam::frontend {

double squared_distance(const DistanceField& field, std::span<const Eigen::Vector2d> points,
                        const slam::Pose2& pose) {
  double sum = 0.0;
  for (const Eigen::Vector2d& p : points) {
    const double d = field.interpolate(pose * p);
    sum += d * d;
  }
  return sum;
}

namespace {

/// J^T J and J^T r of the residuals r_j = d(pose * p_j).
double normal_equations(const DistanceField& field, std::span<const Eigen::Vector2d> points,
                        const slam::Pose2& pose, Eigen::Matrix3d& jtj, Eigen::Vector3d& jtr) {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  jtj.setZero();
  jtr.setZero();
  double cost = 0.0;
  for (const Eigen::Vector2d& p : points) {
    Eigen::Vector2d g;
    const double d = field.interpolate(pose * p, &g);
    cost += d * d;
    // d(pose * p) / d(x, y, theta) = [I | (-s px - c py, c px - s py)].
    const Eigen::Vector3d j(g.x(), g.y(),
                            g.x() * (-s * p.x() - c * p.y()) + g.y() * (c * p.x() - s * p.y()));
    jtj.noalias() += j * j.transpose();
    jtr.noalias() += j * d;
  }
  return cost;
}

}  // namespace

Refinement refine_pose(const DistanceField& field, std::span<const Eigen::Vector2d> points,
                       const slam::Pose2& start, int iterations, double max_shift,
                       double max_turn) {
  Refinement out{start, Eigen::Matrix3d::Zero()};
  Eigen::Vector3d jtr;
  double cost = normal_equations(field, points, out.pose, out.hessian, jtr);
  double lambda = 1e-3;
  for (int it = 0; it < iterations; ++it) {
    Eigen::Matrix3d damped = out.hessian;
    damped.diagonal() += lambda * (out.hessian.diagonal().array() + 1e-9).matrix();
    const Eigen::Vector3d step = -damped.ldlt().solve(jtr);
    if (!step.allFinite()) break;
    const slam::Pose2 trial{
        std::clamp(out.pose.x + step.x(), start.x - max_shift, start.x + max_shift),
        std::clamp(out.pose.y + step.y(), start.y - max_shift, start.y + max_shift),
        slam::wrap_angle(start.theta +
                         std::clamp(slam::wrap_angle(out.pose.theta + step.z() - start.theta),
                                    -max_turn, max_turn))};
    Eigen::Matrix3d trial_jtj;
    Eigen::Vector3d trial_jtr;
    const double trial_cost = normal_equations(field, points, trial, trial_jtj, trial_jtr);
    if (trial_cost < cost) {
      out = {trial, trial_jtj};
      jtr = trial_jtr;
      const bool converged = cost - trial_cost < 1e-9 * (1.0 + cost);
      cost = trial_cost;
      lambda = std::max(lambda / 10.0, 1e-7);
      if (converged) break;
    } else {
      lambda *= 10.0;
      if (lambda > 1e4) break;
    }
  }
  return out;
}

Eigen::Matrix3d laplace_covariance(const Eigen::Matrix3d& hessian, const LikelihoodModel& model,
                                   const PosteriorSettings& settings) {
  // Information of the posterior plus a weak prior as wide as the largest search box.
  const double scale = model.sigma * model.sigma * model.temperature;
  Eigen::Matrix3d information = hessian / scale;
  information(0, 0) += 1.0 / (settings.max_linear * settings.max_linear);
  information(1, 1) += 1.0 / (settings.max_linear * settings.max_linear);
  information(2, 2) += 1.0 / (settings.max_angular * settings.max_angular);
  return information.ldlt().solve(Eigen::Matrix3d::Identity());
}

namespace {

Eigen::Vector3d box_half_widths(const Eigen::Matrix3d& covariance, double sigmas,
                                const PosteriorSettings& s) {
  Eigen::Vector3d h;
  for (int k = 0; k < 3; ++k) h[k] = sigmas * std::sqrt(std::max(covariance(k, k), 0.0));
  h.x() = std::clamp(h.x(), s.min_linear, s.max_linear);
  h.y() = std::clamp(h.y(), s.min_linear, s.max_linear);
  h.z() = std::clamp(h.z(), s.min_angular, s.max_angular);
  return h;
}

/// Candidates on the box lattice around `center`, weighted by the model.
std::vector<WeightedPose> box_candidates(const DistanceField& field, const LikelihoodModel& model,
                                         std::span<const Eigen::Vector2d> points,
                                         const slam::Pose2& center, const Eigen::Vector3d& spacing,
                                         int steps) {
  std::vector<WeightedPose> out;
  const double scale = -1.0 / (2.0 * model.sigma * model.sigma * model.temperature);
  std::vector<Eigen::Vector2d> rotated(points.size());
  for (int l = -steps; l <= steps; ++l) {
    const double theta = slam::wrap_angle(center.theta + l * spacing.z());
    const slam::Pose2 rotation{0.0, 0.0, theta};
    for (std::size_t j = 0; j < points.size(); ++j) rotated[j] = rotation * points[j];
    for (int iy = -steps; iy <= steps; ++iy)
      for (int ix = -steps; ix <= steps; ++ix) {
        const Eigen::Vector2d t(center.x + ix * spacing.x(), center.y + iy * spacing.y());
        double sum = 0.0;
        for (const Eigen::Vector2d& q : rotated) {
          const double d = field.interpolate(q + t);
          sum += d * d;
        }
        out.push_back({slam::Pose2{t.x(), t.y(), theta}, scale * sum});
      }
  }
  return out;
}

}  // namespace

PosteriorSamples posterior_samples(const DistanceField& field, const LikelihoodModel& model,
                                   std::span<const Eigen::Vector2d> points,
                                   const slam::Pose2& center, const Eigen::Matrix3d& guess,
                                   const PosteriorSettings& settings) {
  const int steps = std::max(1, settings.steps);
  Eigen::Vector3d half = box_half_widths(guess, 3.0, settings);
  PosteriorSamples out{{}, center, half / steps};
  for (int round = 0; round < std::max(1, settings.rounds); ++round) {
    out.spacing = half / steps;
    out.candidates = box_candidates(field, model, points, center, out.spacing, steps);
    const Eigen::Vector3d refit =
        box_half_widths(posterior_gaussian(out).covariance(), 3.5, settings);
    const double change = (refit.array() / half.array()).log().abs().maxCoeff();
    half = refit;
    if (change < std::log(1.3)) break;
  }
  return out;
}

slam::Gaussian2 posterior_gaussian(const PosteriorSamples& samples, const slam::Pose2& anchor) {
  const Eigen::Matrix3d cell = (samples.spacing.array().square() / 12.0).matrix().asDiagonal();
  std::vector<WeightedPose> moved = samples.candidates;
  for (WeightedPose& c : moved) c.pose = c.pose * anchor;
  return moment_match(moved,
                      compose_covariance(samples.center, cell, anchor, Eigen::Matrix3d::Zero()));
}

}  // namespace antslam::frontend
