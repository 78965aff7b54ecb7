#pragma once
// Scoring a corrected map against ground truth: the absolute trajectory error of the fragment
// frames after the rigid 2D transform that best aligns them to the reference (Umeyama's least
// squares without scale), and readers for the reference files of data/posegraphs.

#include <cstddef>
#include <filesystem>
#include <span>
#include <vector>

#include "slamgraph/pose2.hpp"

namespace antslam::slam {

struct TrajectoryError {
  double rmse_m = 0.0;    ///< root mean square translation error, metres
  double max_m = 0.0;     ///< largest translation error, metres
  double rmse_rad = 0.0;  ///< root mean square heading error, radians
  std::size_t poses = 0;  ///< poses compared
};

/// Throws std::invalid_argument if the sizes differ or are zero.
TrajectoryError absolute_trajectory_error(std::span<const Pose2> estimate,
                                          std::span<const Pose2> reference);

/// Reference poses: a .g2o file (its vertices), a TUM trajectory (.tum) or lines of
/// `x y theta` (e.g. manhattan3500.gt.dat). Throws std::runtime_error "source:line: problem".
std::vector<Pose2> read_reference_poses(const std::filesystem::path& path);

}  // namespace antslam::slam
