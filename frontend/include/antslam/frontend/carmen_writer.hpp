#pragma once
// Writes laser logs in the CARMEN text format that parse_carmen reads (laser_log.hpp): '#'
// comments, PARAM lines for the FLASER geometry, then the FLASER and ODOM messages merged in
// time order. Numbers are written in their shortest exact form, so reading a written log gives
// back the same ranges, positions and timestamps; headings and the field of view come back up
// to one rounding step (the reader wraps angles; CARMEN's field of view is in degrees).

#include <iosfwd>
#include <span>
#include <string>

#include "antslam/frontend/laser_log.hpp"

namespace antslam::frontend {

/// Writes `log` as PARAM, FLASER and ODOM lines (FLASER's pose fields both hold the odometry;
/// ODOM's velocities are written as 0). Each comment becomes a '#' line at the top. Throws
/// std::invalid_argument naming the scan or field that FLASER lines cannot carry: a geometry
/// other than the log's FLASER geometry (first beam at -fov/2, beams evenly spread over the
/// field of view, laser on the robot's x axis), fewer than 2 readings, negative or non-finite
/// numbers, a comment with a line break.
void write_carmen(std::ostream& out, const LaserLog& log,
                  std::span<const std::string> comments = {});

}  // namespace antslam::frontend
