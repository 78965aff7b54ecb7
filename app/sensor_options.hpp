#pragma once
// The laser geometry options of the commands that read CARMEN logs (--fov, --first-beam,
// --max-range, --laser-offset), registered once.

#include <CLI/CLI.hpp>

#include <filesystem>
#include <optional>

#include "antslam/frontend/laser_log.hpp"

namespace antslam::cli {

struct SensorOptions {
  std::optional<double> fov_degrees;         ///< degrees, --fov
  std::optional<double> first_beam_degrees;  ///< degrees, --first-beam
  std::optional<double> max_range;           ///< metres, --max-range
  std::optional<double> laser_offset;        ///< metres, --laser-offset

  /// The overrides for frontend::read_carmen_file (angles in radians).
  frontend::SensorOverrides overrides() const;
};

void add_sensor_options(CLI::App& command, SensorOptions& options);

/// Reads a CARMEN log with the options' geometry and prints each of the reader's warnings
/// (sensor_check.hpp) as one line "warning: LOG: ..." on stderr.
frontend::LaserLog read_laser_log(const std::filesystem::path& path, const SensorOptions& options);

}  // namespace antslam::cli
