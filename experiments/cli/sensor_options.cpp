#include "sensor_options.hpp"

#include <cstdio>
#include <numbers>

namespace antslam::cli {

frontend::SensorOverrides SensorOptions::overrides() const {
  constexpr double radians = std::numbers::pi / 180.0;
  frontend::SensorOverrides o;
  if (fov_degrees) o.field_of_view = *fov_degrees * radians;
  if (first_beam_degrees) o.first_angle = *first_beam_degrees * radians;
  o.max_range = max_range;
  o.laser_offset = laser_offset;
  return o;
}

frontend::LaserLog read_laser_log(const std::filesystem::path& path, const SensorOptions& options) {
  frontend::LaserLog log = frontend::read_carmen_file(path, options.overrides());
  for (const std::string& w : log.warnings)
    std::fprintf(stderr, "warning: %s: %s\n", path.string().c_str(), w.c_str());
  return log;
}

void add_sensor_options(CLI::App& command, SensorOptions& options) {
  command.add_option("--fov", options.fov_degrees,
                     "laser field of view, degrees (overrides the log)");
  command.add_option("--first-beam", options.first_beam_degrees,
                     "angle of the first beam, degrees (default -fov/2; overrides the log)");
  command.add_option("--max-range", options.max_range,
                     "laser maximum range, metres: readings at or above are no-returns");
  command.add_option("--laser-offset", options.laser_offset,
                     "laser position ahead of the robot origin, metres (overrides the log)");
}

}  // namespace antslam::cli
