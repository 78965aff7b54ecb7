#pragma once
// Time-stamped 2D trajectories and the TUM trajectory format
// (`timestamp x y z qx qy qz qw` per line, '#' comments), used to exchange trajectories with
// other SLAM systems and evaluation tools.

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "antslam/slamgraph/pose2.hpp"

namespace antslam::slam {

/// The largest coordinate (metres) and timestamp (seconds) magnitudes the readers accept. Beyond
/// them sums of squares over a trajectory could overflow or lose every digit, and an evaluation
/// would print inf or nan; no robot log comes near (1e9 m is more than twice the distance to the
/// moon, 1e12 s more than 30,000 years).
inline constexpr double kMaxCoordinate = 1e9;
inline constexpr double kMaxTimestamp = 1e12;

struct StampedPose {
  double stamp = 0.0;  ///< seconds
  Pose2 pose;
};

using Trajectory = std::vector<StampedPose>;

/// Reads a TUM trajectory; the yaw is taken from the quaternion (normalised: its norm may miss 1
/// by 1 %), z and roll/pitch are ignored. Throws std::runtime_error "source:line: problem" on
/// malformed lines (wrong field count, non-numbers, non-finite values, positions beyond
/// kMaxCoordinate, timestamps beyond kMaxTimestamp, a quaternion whose norm is not 1) and on
/// timestamps that decrease.
Trajectory read_tum(std::istream& in, const std::string& source);
Trajectory read_tum_file(const std::filesystem::path& path);

/// The length of the path through the trajectory's positions, metres.
double path_length(const Trajectory& trajectory);

/// Writes one line per pose with z = 0 and a yaw-only quaternion; timestamps with microseconds.
/// Throws std::invalid_argument, writing nothing, for what read_tum refuses: non-finite values,
/// magnitudes beyond the limits above, timestamps that decrease.
void write_tum(std::ostream& out, const Trajectory& trajectory);

}  // namespace antslam::slam
