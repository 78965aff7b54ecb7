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

#include "antslam/slamgraph/pose2.hpp"
#include "antslam/slamgraph/trajectory.hpp"

namespace antslam::frontend {

/// The most a planar laser can plausibly measure, and how far from the robot origin it can be
/// mounted (metres). Logs and command lines beyond these are refused: a laser 1e308 m ahead of
/// the robot would need a map of 1e308 m.
inline constexpr double kMaxLaserRange = 1000.0;
inline constexpr double kMaxLaserOffset = 10.0;

/// The one check of each geometry value, for PARAM lines, ROBOTLASER1 fields and command-line
/// overrides alike: why the value cannot be that field, or empty if it can.
std::string field_of_view_problem(double radians);  ///< needs (0, 2 pi]
std::string first_angle_problem(double radians);    ///< needs [-2 pi, 2 pi]
std::string max_range_problem(double metres);       ///< needs (0, kMaxLaserRange]
std::string laser_offset_problem(double metres);    ///< needs |offset| <= kMaxLaserOffset

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
  std::size_t line = 0;       ///< line of the source it was read from (0: not read), for messages

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
/// last value in the file wins; `overrides` win over everything. The geometry every scan ends up
/// with is then checked once (the *_problem functions above), and the scans are checked
/// (check_sensor: no-return spikes, readings above the maximum, beams against the field of
/// view), which may add warnings. Throws std::invalid_argument on an override out of range,
/// std::runtime_error "source:line: problem" on malformed lines (wrong field counts,
/// non-numbers, non-finite or negative values, coordinates beyond slam::kMaxCoordinate,
/// timestamps beyond slam::kMaxTimestamp, readings beyond the largest float), on geometry out of
/// range (naming the PARAM or ROBOTLASER1 line it came from) and on a log without scans.
LaserLog parse_carmen(std::string_view text, const std::string& source,
                      const SensorOverrides& overrides = {});

/// Throws std::runtime_error "source:line: ..." naming the first scan whose timestamp is earlier
/// than the one before: the trajectory of such a log cannot be written as a TUM file (which
/// lists poses in time order), so the commands that write one call this before any work.
void require_time_order(const LaserLog& log);

/// Reads a CARMEN log file, gzip-compressed or not (detected from the content).
/// Throws std::runtime_error naming the file if it cannot be read.
LaserLog read_carmen_file(const std::filesystem::path& path, const SensorOverrides& overrides = {});

/// The whole content of a file, decompressed if it is gzip data.
std::string read_maybe_gzipped(const std::filesystem::path& path);

}  // namespace antslam::frontend
