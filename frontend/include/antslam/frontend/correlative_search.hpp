#pragma once
// Exhaustive correlative scan matching (Olson 2009) on a distance field: every rotation of the
// window, every translation on the field's lattice, scored by the sum of squared distances of
// the moved points to the nearest map hit (i.e. minus twice sigma^2 times the log-likelihood of
// the likelihood field). The rotated point set is computed once per rotation and the
// translations slide it over contiguous memory, so the inner loop is a vectorisable sum.

#include <Eigen/Core>
#include <span>
#include <vector>

#include "antslam/frontend/distance_field.hpp"
#include "antslam/slamgraph/pose2.hpp"

namespace antslam::frontend {

struct SearchWindow {
  double linear = 0.5;          ///< metres, half-width of the window in x and in y
  double angular = 0.35;        ///< radians, half-width of the window in heading
  double angular_step = 0.017;  ///< radians between tried headings
};

/// A weak Gaussian prior on the pose (the odometry prediction), added to the score as
/// weight * (|t - t0|^2 / linear_std^2 + (theta - theta0)^2 / angular_std^2): it decides between
/// poses the scan cannot tell apart (along a corridor) without moving a well-constrained match.
struct PosePrior {
  slam::Pose2 mean;          ///< the predicted pose
  double linear_std = 1.0;   ///< metres
  double angular_std = 1.0;  ///< radians
  double weight = 0.0;       ///< m^2 (the units of the score); 0: no prior
};

struct SearchResult {
  slam::Pose2 pose;               ///< the best pose on the search lattice
  double squared_distance = 0.0;  ///< sum over points of d^2 (m^2) at that pose
  double score = 0.0;             ///< squared_distance plus the prior's penalty (m^2)
};

/// Finds the pose in the window around `center` whose moved `points` (robot frame) lie closest
/// to the map (lowest score); translations step by the field's resolution. Grows the field to
/// cover the window (new cells read as max distance). Ties keep the candidate met first
/// (rotation-major order, from the most negative offsets), so results are deterministic.
SearchResult correlative_search(DistanceField& field, std::span<const Eigen::Vector2d> points,
                                const slam::Pose2& center, const SearchWindow& window,
                                const PosePrior& prior = {});

/// The best poses of up to `peaks` separate peaks of the score, best first: no two of them lie
/// within two lattice steps (in x, y and heading) of each other.
std::vector<SearchResult> correlative_peaks(DistanceField& field,
                                            std::span<const Eigen::Vector2d> points,
                                            const slam::Pose2& center, const SearchWindow& window,
                                            const PosePrior& prior, std::size_t peaks);

}  // namespace antslam::frontend
