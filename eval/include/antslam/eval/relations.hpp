#pragma once
// Relations files of Kuemmerle et al. 2009 ("On measuring the accuracy of SLAM algorithms"): one
// relation a line, `t1 t2 dx dy dz droll dpitch dyaw`, the relative motion from the pose at time
// t1 to the pose at time t2 expressed in the frame of the pose at t1 (metres, radians). Blank
// lines and lines starting with '#' are skipped. These are 2D relations: dz, droll and dpitch
// must be 0.

#include <cstddef>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "antslam/slamgraph/pose2.hpp"

namespace antslam::eval {

struct Relation {
  double stamp1 = 0.0;   ///< seconds
  double stamp2 = 0.0;   ///< seconds
  slam::Pose2 motion;    ///< reference motion from the pose at stamp1 to the pose at stamp2
  std::size_t line = 0;  ///< line of the source file, for messages
};

/// Throws std::runtime_error "source:line: problem" on malformed lines (wrong field count,
/// non-numbers, non-finite values, non-zero dz/droll/dpitch) and "source: no relations" if there
/// is none.
std::vector<Relation> read_relations(std::istream& in, const std::string& source);
std::vector<Relation> read_relations_file(const std::filesystem::path& path);

}  // namespace antslam::eval
