#pragma once
// Laser logs in the CARMEN text format (paper Sec. IV: SICK LMS logs): FLASER, ROBOTLASER1 and
// ODOM messages, PARAM lines for the sensor geometry, '#' comments; plain or gzip-compressed.
//
// Every scan carries its own geometry (first-beam angle, angular step, max range, laser pose on
// the robot), so logs with several sensor set-ups and ROBOTLASER1 lines (which describe
// themselves) need no special cases downstream.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "slamgraph/pose2.hpp"
#include "slamgraph/trajectory.hpp"

namespace antslam::frontend {

/// Geometry of a planar laser scanner: beam k points at first_angle + k * angle_step in the laser
/// frame; ranges at or above max_range mean "no return".
struct SensorGeometry {
  double field_of_view = 3.141592653589793;  ///< radians, first to last beam (FLASER: 180 deg)
  std::optional<double> first_angle;         ///< radians; none: -field_of_view / 2
  double max_range = 80.0;                   ///< metres; readings >= this are "no return"
  slam::Pose2 laser_pose;                    ///< laser frame in the robot frame (x forward)
  std::optional<double> angle_step;          ///< radians between beams, if the log declares it
                                             ///< (without a field of view: it sets the field)
  bool field_of_view_declared = false;       ///< a PARAM line or an override gave it
  bool max_range_declared = false;           ///< a PARAM line or an override gave it
};

/// Command-line overrides; each set field replaces what the log says (PARAM lines and
/// ROBOTLASER1 fields) for every scan.
struct SensorOverrides {
  std::optional<double> field_of_view;  ///< radians
  std::optional<double> first_angle;    ///< radians
  std::optional<double> max_range;      ///< metres
  std::optional<double> laser_offset;   ///< metres ahead of the robot origin (laser x)
};

struct LaserScan {
  double stamp = 0.0;         ///< seconds (the message's timestamp field)
  slam::Pose2 odometry;       ///< raw odometry pose of the robot origin when the scan was taken
  slam::Pose2 laser_pose;     ///< laser frame in the robot frame
  double first_angle = 0.0;   ///< radians, direction of beam 0 in the laser frame
  double angle_step = 0.0;    ///< radians between consecutive beams (counter-clockwise > 0)
  double max_range = 80.0;    ///< metres; readings >= this are "no return"
  std::vector<float> ranges;  ///< metres, one per beam

  double beam_angle(std::size_t k) const {
    return first_angle + static_cast<double>(k) * angle_step;
  }
};

struct LaserLog {
  std::string source;                 ///< file name (for messages)
  std::vector<LaserScan> scans;       ///< FLASER and ROBOTLASER1 messages, in file order
  slam::Trajectory odometry;          ///< ODOM messages, in file order
  SensorGeometry flaser_geometry;     ///< geometry applied to FLASER scans (PARAMs + overrides)
  std::size_t skipped_messages = 0;   ///< lines of other message types (SYNC, NEFF, RAWLASER, ...)
  std::vector<std::string> warnings;  ///< one line each: what the reader found doubtful or changed
                                      ///< (sensor_check.hpp)
};

/// Parses a CARMEN log held in memory. `source` names it in error messages. PARAM lines set the
/// FLASER geometry (laser_front_laser_fov in degrees, or radians if <= 2 pi;
/// laser_front_laser_resolution in degrees, which without a field of view makes it the
/// resolution times the beams less one; robot_front_laser_max; robot_frontlaser_offset); the
/// last value in the file wins; `overrides` win over everything. The scans are then checked
/// (check_sensor: no-return spikes, readings above the maximum, beams against the field of
/// view), which may add warnings. Throws std::runtime_error "source:line: problem" on malformed
/// lines (wrong field counts, non-numbers, non-finite or negative values) and on a log without
/// scans.
LaserLog parse_carmen(std::string_view text, const std::string& source,
                      const SensorOverrides& overrides = {});

/// Reads a CARMEN log file, gzip-compressed or not (detected from the content).
/// Throws std::runtime_error naming the file if it cannot be read.
LaserLog read_carmen_file(const std::filesystem::path& path, const SensorOverrides& overrides = {});

/// The whole content of a file, decompressed if it is gzip data.
std::string read_maybe_gzipped(const std::filesystem::path& path);

}  // namespace antslam::frontend
