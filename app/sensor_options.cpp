#include "sensor_options.hpp"

#include <cstdio>
#include <limits>
#include <numbers>
#include <string>

#include "validators.hpp"

namespace antslam::cli {

namespace {

constexpr double kRadians = std::numbers::pi / 180.0;

/// A finite number that the laser log's own check of the field accepts (frontend/laser_log.hpp),
/// `scale` converting the option's unit to the field's.
CLI::Validator geometry(std::string (*problem)(double), double scale) {
  return CLI::Validator(
      [problem, scale](std::string& text) -> std::string {
        constexpr double kLargest = std::numeric_limits<double>::max();
        const std::string not_finite = finite_in(-kLargest, kLargest)(text);
        if (!not_finite.empty()) return not_finite;
        return problem(std::stod(text) * scale);
      },
      "");
}

}  // namespace

frontend::SensorOverrides SensorOptions::overrides() const {
  frontend::SensorOverrides o;
  if (fov_degrees) o.field_of_view = *fov_degrees * kRadians;
  if (first_beam_degrees) o.first_angle = *first_beam_degrees * kRadians;
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
  command
      .add_option("--fov", options.fov_degrees, "laser field of view, degrees (overrides the log)")
      ->check(geometry(frontend::field_of_view_problem, kRadians));
  command
      .add_option("--first-beam", options.first_beam_degrees,
                  "angle of the first beam, degrees (default -fov/2; overrides the log)")
      ->check(geometry(frontend::first_angle_problem, kRadians));
  command
      .add_option("--max-range", options.max_range,
                  "laser maximum range, metres: readings at or above are no-returns")
      ->check(geometry(frontend::max_range_problem, 1.0));
  command
      .add_option("--laser-offset", options.laser_offset,
                  "laser position ahead of the robot origin, metres (overrides the log)")
      ->check(geometry(frontend::laser_offset_problem, 1.0));
}

}  // namespace antslam::cli
