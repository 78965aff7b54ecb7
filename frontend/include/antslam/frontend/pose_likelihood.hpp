#pragma once
// The measurement model p(z | m, x) of the scan matcher on a distance field, its local
// maximisation (Gauss-Newton) and the Gaussian of eqs. (5)-(6) around the maximum.
//
// Model: log p(z | m, x) = -(1 / T) sum_j d(x (+) z_j)^2 / (2 sigma^2), d interpolated
// bilinearly and clamped at the field's max distance. The temperature T >= 1 accounts for what
// independent beams ignore (neighbouring beams see the same wall, the map itself is noisy); it
// is calibrated so that the covariance is honest (NEES about 3, docs/frontend.md).

#include <Eigen/Core>
#include <span>
#include <vector>

#include "antslam/frontend/distance_field.hpp"
#include "antslam/frontend/pose_covariance.hpp"
#include "antslam/slamgraph/gaussian2.hpp"
#include "antslam/slamgraph/pose2.hpp"

namespace antslam::frontend {

struct LikelihoodModel {
  double sigma = 0.05;       ///< metres, std of a hit around the nearest map hit
  double temperature = 1.0;  ///< dimensionless, divides the log-likelihood
};

/// sum_j d(pose * p_j)^2 in m^2 (bilinear distances).
double squared_distance(const DistanceField& field, std::span<const Eigen::Vector2d> points,
                        const slam::Pose2& pose);

struct Refinement {
  slam::Pose2 pose;         ///< the local minimum of sum_j d^2 near the start
  Eigen::Matrix3d hessian;  ///< Gauss-Newton J^T J of sum_j d^2 at that pose (1/m^2 units)
};

/// Levenberg-Marquardt on sum_j d(pose * p_j)^2, at most `iterations` steps, staying within
/// `max_shift` metres (x and y each) and `max_turn` radians of `start` (a sub-cell refinement
/// must not slide along a corridor); never returns a pose worse than `start`.
Refinement refine_pose(const DistanceField& field, std::span<const Eigen::Vector2d> points,
                       const slam::Pose2& start, int iterations, double max_shift, double max_turn);

struct PosteriorSettings {
  int steps = 3;                ///< candidates per side and axis: (2 steps + 1)^3 in all
  int rounds = 3;               ///< at most this many re-fits of the candidate box
  double min_linear = 0.002;    ///< metres, smallest half-width of the box in x and y
  double max_linear = 0.5;      ///< metres, largest half-width in x and y
  double min_angular = 0.0005;  ///< radians, smallest half-width in heading
  double max_angular = 0.2;     ///< radians, largest half-width in heading
};

/// The candidate set of eqs. (5)-(6): poses x_k on a box lattice around `center` (the set
/// {x : |x - x_hat| <= Delta}), each with log p(z | m, x_k).
struct PosteriorSamples {
  std::vector<WeightedPose> candidates;  ///< poses and log-likelihoods
  slam::Pose2 center;                    ///< x_hat
  Eigen::Vector3d spacing;               ///< lattice steps (m, m, rad)
};

/// Delta starts at 3 sigma of `guess` (a covariance estimate, e.g. the Laplace approximation)
/// and is re-fitted to 3.5 sigma of the moment-matched result, within the settings' limits.
PosteriorSamples posterior_samples(const DistanceField& field, const LikelihoodModel& model,
                                   std::span<const Eigen::Vector2d> points,
                                   const slam::Pose2& center, const Eigen::Matrix3d& guess,
                                   const PosteriorSettings& settings);

/// Eqs. (5)-(6) over the candidates moved by `anchor` (pose * anchor; identity: the pose
/// itself; a loop closure puts its anchor point there). Each candidate stands for its lattice
/// cell, whose own spread (h^2 / 12 per axis) is added.
slam::Gaussian2 posterior_gaussian(const PosteriorSamples& samples, const slam::Pose2& anchor = {});

/// Laplace approximation of the posterior covariance from a Gauss-Newton Hessian of
/// sum_j d^2: T sigma^2 (J^T J)^-1, with unconstrained directions capped by the settings' max.
Eigen::Matrix3d laplace_covariance(const Eigen::Matrix3d& hessian, const LikelihoodModel& model,
                                   const PosteriorSettings& settings);

}  // namespace antslam::frontend
