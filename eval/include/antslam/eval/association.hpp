#pragma once
// Association of an estimated trajectory with a reference by timestamp, as the TUM benchmark's
// associate.py: among all (estimate, reference) pairs whose stamps differ by at most max_dt, the
// pair with the smallest difference is taken first, then the next smallest among the poses still
// free, and so on (nearest neighbour, one-to-one). Ties go to the earlier estimate, then the
// earlier reference pose. Trajectories must have non-decreasing timestamps (read_tum ensures it).

#include <cstddef>
#include <optional>
#include <vector>

#include "antslam/slamgraph/trajectory.hpp"

namespace antslam::eval {

/// One estimated pose and the reference pose it was associated with.
struct PosePair {
  std::size_t estimate_index = 0;   ///< index in the estimated trajectory
  std::size_t reference_index = 0;  ///< index in the reference trajectory
  double stamp = 0.0;               ///< reference timestamp, seconds
  slam::Pose2 estimate;             ///< estimated pose (metres, radians)
  slam::Pose2 reference;            ///< reference pose (metres, radians)
};

/// The associated pairs in reference order. Poses with no partner within max_dt are left out.
/// Throws std::invalid_argument if max_dt is negative or not finite, or if a trajectory's
/// timestamps decrease. Runs in O((n + m) log m) for typical tolerances.
std::vector<PosePair> associate(const slam::Trajectory& estimate, const slam::Trajectory& reference,
                                double max_dt);

/// Index of the pose whose stamp is nearest to `stamp` (the earlier one on a tie), if it lies
/// within max_dt; `trajectory` must have non-decreasing timestamps.
std::optional<std::size_t> find_stamp(const slam::Trajectory& trajectory, double stamp,
                                      double max_dt);

}  // namespace antslam::eval
