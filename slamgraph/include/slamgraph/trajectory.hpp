#pragma once
// Time-stamped 2D trajectories and the TUM trajectory format
// (`timestamp x y z qx qy qz qw` per line, '#' comments), used to exchange trajectories with
// other SLAM systems and evaluation tools.

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "slamgraph/pose2.hpp"

namespace antslam::slam {

struct StampedPose {
  double stamp = 0.0;  ///< seconds
  Pose2 pose;
};

using Trajectory = std::vector<StampedPose>;

/// Reads a TUM trajectory; the yaw is taken from the quaternion, z and roll/pitch are ignored.
/// Throws std::runtime_error "source:line: problem" on malformed lines (wrong field count,
/// non-numbers, non-finite values, zero quaternion) and on timestamps that decrease.
Trajectory read_tum(std::istream& in, const std::string& source);
Trajectory read_tum_file(const std::filesystem::path& path);

/// The length of the path through the trajectory's positions, metres.
double path_length(const Trajectory& trajectory);

/// Writes one line per pose with z = 0 and a yaw-only quaternion; timestamps with microseconds.
void write_tum(std::ostream& out, const Trajectory& trajectory);

}  // namespace antslam::slam
