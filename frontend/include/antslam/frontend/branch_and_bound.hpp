#pragma once
// Branch-and-bound correlative matching (Hess et al. 2016, Sec. V): the exact best lattice pose
// of a point set within a large window, found without scoring every pose. Every heading of the
// window is tried; translations are split recursively into 2^h x 2^h blocks whose best possible
// score (from a LikelihoodPyramid) bounds all poses inside, and blocks that cannot beat the
// best pose found so far are skipped.

#include <Eigen/Core>
#include <optional>
#include <span>

#include "antslam/frontend/likelihood_pyramid.hpp"
#include "antslam/slamgraph/pose2.hpp"

namespace antslam::frontend {

struct SearchBox {
  slam::Pose2 center;          ///< the pose the window is centred on
  double linear_x = 1.0;       ///< metres, half-width in x
  double linear_y = 1.0;       ///< metres, half-width in y
  double angular = 0.2;        ///< radians, half-width in heading
  double angular_step = 0.01;  ///< radians between headings
};

/// Poses near `pose` (within `linear` metres in x and y and `angular` radians) are not
/// candidates: used to look for a second, separate peak.
struct Exclusion {
  slam::Pose2 pose;
  double linear = 0.0;   ///< metres
  double angular = 0.0;  ///< radians
};

struct ScoredPose {
  slam::Pose2 pose;    ///< on the lattice of the window
  double score = 0.0;  ///< mean level-0 likelihood of the points, in [0, 1]
};

/// The best lattice pose of `points` in the box scoring above `min_score`, if any (ties: the
/// first in heading-major, then search, order, deterministic).
std::optional<ScoredPose> branch_and_bound(const LikelihoodPyramid& pyramid,
                                           std::span<const Eigen::Vector2d> points,
                                           const SearchBox& box, double min_score,
                                           const std::optional<Exclusion>& exclusion = {});

/// The mean level-0 likelihood of the points at a pose (nearest lattice cells).
double lattice_score(const LikelihoodPyramid& pyramid, std::span<const Eigen::Vector2d> points,
                     const slam::Pose2& pose);

}  // namespace antslam::frontend
