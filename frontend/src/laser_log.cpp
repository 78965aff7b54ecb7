#include "antslam/frontend/laser_log.hpp"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "antslam/frontend/sensor_check.hpp"

namespace antslam::frontend {

namespace {

using Tokens = std::vector<std::string_view>;

/// Readings beyond the laser's range are no-returns, whatever their value, but they are kept
/// as floats: beyond the largest float a reading is not a number the scan can hold.
constexpr double kMaxReading = std::numeric_limits<float>::max();

void split(std::string_view line, Tokens& tokens) {
  tokens.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
}

bool is_message_name(std::string_view token) {
  for (const char c : token)
    if (!((c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_')) return false;
  return !token.empty() && token[0] >= 'A' && token[0] <= 'Z';
}

/// Reads the fields of one line, naming the line in every error.
class LineReader {
 public:
  LineReader(const std::string& source, std::size_t line, const Tokens& tokens)
      : source_(source), line_(line), tokens_(tokens) {}

  [[noreturn]] void fail(const std::string& problem) const {
    throw std::runtime_error(source_ + ":" + std::to_string(line_) + ": " + problem);
  }

  void require(std::size_t count, std::string_view what) const {
    if (tokens_.size() < count)
      fail(std::string(tokens_[0]) + " has " + std::to_string(tokens_.size()) +
           " fields, expected at least " + std::to_string(count) + " (" + std::string(what) + ")");
  }

  double number(std::size_t index, std::string_view field) const {
    const std::string_view token = tokens_.at(index);
    double value = 0.0;
    const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc() || ptr != token.data() + token.size())
      fail(std::string(field) + " '" + std::string(token) + "' is not a number");
    if (!std::isfinite(value)) fail(std::string(field) + " is not finite");
    return value;
  }

  std::size_t count(std::size_t index, std::string_view field) const {
    const std::string_view token = tokens_.at(index);
    std::size_t value = 0;
    const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc() || ptr != token.data() + token.size() || value > 100000)
      fail(std::string(field) + " '" + std::string(token) + "' is not a count");
    return value;
  }

  /// A number of magnitude at most `limit` (what the field's `unit` can plausibly reach).
  double bounded(std::size_t index, std::string_view field, double limit,
                 std::string_view unit) const {
    const double value = number(index, field);
    if (std::abs(value) > limit) {
      std::ostringstream problem;
      problem << field << " " << value << " " << unit << " is beyond " << limit << " " << unit;
      fail(problem.str());
    }
    return value;
  }

  slam::Pose2 pose(std::size_t index, std::string_view field) const {
    return {bounded(index, field, slam::kMaxCoordinate, "m"),
            bounded(index + 1, field, slam::kMaxCoordinate, "m"),
            slam::wrap_angle(bounded(index + 2, field, slam::kMaxCoordinate, "rad"))};
  }

  double stamp(std::size_t index) const {
    return bounded(index, "timestamp", slam::kMaxTimestamp, "s");
  }

  std::vector<float> ranges(std::size_t first, std::size_t n) const {
    std::vector<float> out(n);
    for (std::size_t k = 0; k < n; ++k) {
      const std::string field = "range " + std::to_string(k);
      const double r = bounded(first + k, field, kMaxReading, "m");
      if (r < 0.0) fail(field + " is negative");
      out[k] = static_cast<float>(r);
    }
    return out;
  }

  void no_extra_fields(std::size_t allowed) const {
    if (tokens_.size() > allowed)
      fail(std::string(tokens_[0]) + " has " + std::to_string(tokens_.size()) +
           " fields, expected at most " + std::to_string(allowed));
  }

  std::size_t size() const { return tokens_.size(); }

 private:
  const std::string& source_;
  std::size_t line_;
  const Tokens& tokens_;
};

// FLASER n r_1..r_n x y theta odom_x odom_y odom_theta timestamp [host logger_timestamp]
LaserScan parse_flaser(const LineReader& in) {
  in.require(2, "FLASER n ...");
  const std::size_t n = in.count(1, "number of readings");
  if (n < 2) in.fail("FLASER needs at least 2 readings");
  in.require(n + 9, "FLASER n ranges x y theta odom_x odom_y odom_theta timestamp");
  in.no_extra_fields(n + 11);
  LaserScan scan;
  scan.ranges = in.ranges(2, n);
  scan.odometry = in.pose(n + 5, "odometry");
  scan.stamp = in.stamp(n + 8);
  return scan;
}

// ROBOTLASER1 type start_angle fov resolution max_range accuracy remission_mode n r_1..r_n
//   m v_1..v_m laser_x laser_y laser_theta robot_x robot_y robot_theta tv rv forward_safety
//   side_safety turn_axis timestamp [host logger_timestamp]
LaserScan parse_robotlaser1(const LineReader& in) {
  in.require(9, "ROBOTLASER1 type start fov resolution max_range accuracy mode n ...");
  const std::size_t n = in.count(8, "number of readings");
  if (n < 1) in.fail("ROBOTLASER1 needs at least 1 reading");
  in.require(n + 10, "ROBOTLASER1 ... n ranges m");
  const std::size_t m = in.count(n + 9, "number of remissions");
  const std::size_t tail = n + 10 + m;
  in.require(tail + 12, "ROBOTLASER1 ... laser pose, robot pose, 5 values, timestamp");
  in.no_extra_fields(tail + 14);
  LaserScan scan;
  scan.first_angle = in.number(2, "start angle");
  scan.angle_step = in.number(4, "angular resolution");
  scan.max_range = in.number(5, "maximum range");
  scan.ranges = in.ranges(9, n);
  const slam::Pose2 laser = in.pose(tail, "laser pose");
  scan.odometry = in.pose(tail + 3, "robot pose");
  scan.laser_pose = slam::between(scan.odometry, laser);
  scan.stamp = in.stamp(tail + 11);
  return scan;
}

// ODOM x y theta tv rv accel timestamp [host logger_timestamp]
slam::StampedPose parse_odom(const LineReader& in) {
  in.require(8, "ODOM x y theta tv rv accel timestamp");
  in.no_extra_fields(10);
  return {in.stamp(7), in.pose(1, "odometry")};
}

/// Where the FLASER geometry came from: the PARAM line of each value (0: the default).
struct ParamLines {
  std::size_t field_of_view = 0, max_range = 0, offset = 0;
};

// PARAM name value [timestamp host logger_timestamp]: only the laser geometry is used.
void apply_param(const LineReader& in, std::size_t line, const Tokens& tokens,
                 SensorGeometry& geometry, ParamLines& lines) {
  in.require(3, "PARAM name value");
  const std::string_view name = tokens[1];
  if (name == "laser_front_laser_fov") {
    const double fov = in.number(2, "laser_front_laser_fov");
    // CARMEN writes degrees; some converted logs write radians. No laser has a FOV under 6 deg.
    geometry.field_of_view =
        fov <= 2.0 * std::numbers::pi + 1e-6 ? fov : fov * (std::numbers::pi / 180.0);
    geometry.field_of_view_declared = true;
    lines.field_of_view = line;
  } else if (name == "laser_front_laser_resolution") {
    const double degrees = in.number(2, "laser_front_laser_resolution");
    if (!(degrees > 0.0 && degrees <= 10.0))
      in.fail("laser_front_laser_resolution must be in (0, 10] degrees");
    geometry.angle_step = degrees * std::numbers::pi / 180.0;
  } else if (name == "robot_front_laser_max") {
    geometry.max_range = in.number(2, "robot_front_laser_max");
    geometry.max_range_declared = true;
    lines.max_range = line;
  } else if (name == "robot_frontlaser_offset") {
    geometry.laser_pose.x = in.number(2, "robot_frontlaser_offset");
    lines.offset = line;
  }
}

void apply_overrides(const SensorOverrides& o, SensorGeometry& g) {
  if (o.field_of_view) g.field_of_view = *o.field_of_view;
  g.field_of_view_declared = g.field_of_view_declared || o.field_of_view.has_value();
  if (o.first_angle) g.first_angle = *o.first_angle;
  if (o.max_range) g.max_range = *o.max_range;
  g.max_range_declared = g.max_range_declared || o.max_range.has_value();
  if (o.laser_offset) g.laser_pose = slam::Pose2{*o.laser_offset, 0.0, 0.0};
}

void check_overrides(const SensorOverrides& o) {
  const auto check = [](const std::optional<double>& value, std::string (*problem)(double)) {
    if (!value) return;
    const std::string p = problem(*value);
    if (!p.empty()) throw std::invalid_argument(p);
  };
  check(o.field_of_view, field_of_view_problem);
  check(o.first_angle, first_angle_problem);
  check(o.max_range, max_range_problem);
  check(o.laser_offset, laser_offset_problem);
}

/// The first problem of the geometry a scan ends up with, or empty.
std::string geometry_problem(const LaserScan& scan) {
  std::string p = first_angle_problem(scan.first_angle);
  if (p.empty() && scan.ranges.size() > 1)
    p = field_of_view_problem(std::abs(scan.angle_step) *
                              static_cast<double>(scan.ranges.size() - 1));
  if (p.empty()) p = max_range_problem(scan.max_range);
  if (p.empty()) p = laser_offset_problem(std::hypot(scan.laser_pose.x, scan.laser_pose.y));
  return p;
}

/// Checks the FLASER geometry once, naming the PARAM line a bad value came from.
void check_flaser_geometry(const SensorGeometry& g, const ParamLines& lines,
                           const std::string& source) {
  const auto check = [&](const std::string& problem, std::size_t line, const char* param) {
    if (problem.empty()) return;
    throw std::runtime_error(source + (line > 0 ? ":" + std::to_string(line) : "") + ": " +
                             (line > 0 ? std::string("PARAM ") + param + ": " : "") + problem);
  };
  check(field_of_view_problem(g.field_of_view), lines.field_of_view, "laser_front_laser_fov");
  check(first_angle_problem(g.first_angle.value_or(-0.5 * g.field_of_view)), 0, "");
  check(max_range_problem(g.max_range), lines.max_range, "robot_front_laser_max");
  check(laser_offset_problem(g.laser_pose.x), lines.offset, "robot_frontlaser_offset");
}

std::string describe(double value, const char* unit) {
  std::ostringstream text;
  text << value << ' ' << unit;
  return text.str();
}

}  // namespace

std::string field_of_view_problem(double radians) {
  if (radians > 0.0 && radians <= 2.0 * std::numbers::pi * (1.0 + 1e-9)) return {};
  return "field of view " + describe(radians * (180.0 / std::numbers::pi), "degrees") +
         " is not in (0, 360] degrees";
}

std::string first_angle_problem(double radians) {
  if (std::abs(radians) <= 2.0 * std::numbers::pi * (1.0 + 1e-9)) return {};
  return "first beam angle " + describe(radians * (180.0 / std::numbers::pi), "degrees") +
         " is not in [-360, 360] degrees";
}

std::string max_range_problem(double metres) {
  if (metres > 0.0 && metres <= kMaxLaserRange) return {};
  return "maximum range " + describe(metres, "m") + " is not in (0, " +
         describe(kMaxLaserRange, "m]");
}

std::string laser_offset_problem(double metres) {
  if (std::abs(metres) <= kMaxLaserOffset) return {};
  return "laser offset " + describe(metres, "m") + ": the laser must be within " +
         describe(kMaxLaserOffset, "m") + " of the robot origin";
}

LaserLog parse_carmen(std::string_view text, const std::string& source,
                      const SensorOverrides& overrides) {
  check_overrides(overrides);
  LaserLog log;
  log.source = source;
  std::vector<bool> is_flaser;
  ParamLines param_lines;
  Tokens tokens;
  std::size_t line_number = 0;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(begin, end - begin);
    begin = end + 1;
    ++line_number;
    split(line, tokens);
    if (tokens.empty() || tokens[0][0] == '#') continue;
    const LineReader in(source, line_number, tokens);
    const std::string_view type = tokens[0];
    if (type == "FLASER" || type == "ROBOTLASER1") {
      is_flaser.push_back(type == "FLASER");
      log.scans.push_back(is_flaser.back() ? parse_flaser(in) : parse_robotlaser1(in));
      log.scans.back().line = line_number;
    } else if (type == "ODOM") {
      log.odometry.push_back(parse_odom(in));
    } else if (type == "PARAM") {
      apply_param(in, line_number, tokens, log.flaser_geometry, param_lines);
    } else if (is_message_name(type)) {
      ++log.skipped_messages;
    } else {
      in.fail("not a CARMEN message: '" + std::string(type.substr(0, 40)) + "'");
    }
  }
  if (log.scans.empty()) throw std::runtime_error(source + ": no FLASER or ROBOTLASER1 scans");

  SensorGeometry& g = log.flaser_geometry;
  apply_overrides(overrides, g);
  // A declared resolution without a field of view: the first FLASER scan's beams span it.
  const auto first = std::find(is_flaser.begin(), is_flaser.end(), true);
  if (g.angle_step && !g.field_of_view_declared && first != is_flaser.end()) {
    const std::size_t beams =
        log.scans[static_cast<std::size_t>(first - is_flaser.begin())].ranges.size();
    g.field_of_view =
        std::min(2.0 * std::numbers::pi, *g.angle_step * static_cast<double>(beams - 1));
  }
  if (first != is_flaser.end()) check_flaser_geometry(g, param_lines, source);
  const double flaser_first = g.first_angle.value_or(-0.5 * g.field_of_view);
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    LaserScan& scan = log.scans[i];
    if (is_flaser[i]) {
      scan.first_angle = flaser_first;
      scan.angle_step = g.field_of_view / static_cast<double>(scan.ranges.size() - 1);
      scan.max_range = g.max_range;
      scan.laser_pose = g.laser_pose;
      continue;
    }
    if (overrides.field_of_view)
      scan.angle_step = *overrides.field_of_view / static_cast<double>(scan.ranges.size() - 1);
    if (overrides.first_angle) scan.first_angle = *overrides.first_angle;
    if (overrides.max_range) scan.max_range = *overrides.max_range;
    if (overrides.laser_offset) scan.laser_pose = slam::Pose2{*overrides.laser_offset, 0.0, 0.0};
    const std::string problem = geometry_problem(scan);
    if (!problem.empty())
      throw std::runtime_error(source + ":" + std::to_string(scan.line) + ": ROBOTLASER1 " +
                               problem);
  }
  check_sensor(log);
  return log;
}

void require_time_order(const LaserLog& log) {
  for (std::size_t i = 1; i < log.scans.size(); ++i) {
    const LaserScan& a = log.scans[i - 1];
    const LaserScan& b = log.scans[i];
    if (b.stamp >= a.stamp) continue;
    std::ostringstream message;
    message.precision(17);
    message << log.source << ":" << b.line << ": scan timestamp " << b.stamp
            << " s is earlier than " << a.stamp << " s on line " << a.line
            << " (a TUM trajectory needs the scans in time order)";
    throw std::runtime_error(message.str());
  }
}

std::string read_maybe_gzipped(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw std::runtime_error(path.string() + ": is a directory, not a log file");
  // gzread reads gzip data and passes anything else through unchanged.
  gzFile file = gzopen(path.c_str(), "rb");
  if (file == nullptr)
    throw std::runtime_error(path.string() + ": cannot open: " + std::strerror(errno));
  std::string content;
  std::array<char, 1 << 16> buffer{};
  for (;;) {
    const int n = gzread(file, buffer.data(), static_cast<unsigned>(buffer.size()));
    if (n < 0) {
      int code = 0;
      const std::string message = gzerror(file, &code);
      gzclose(file);
      throw std::runtime_error(path.string() + ": cannot read: " + message);
    }
    if (n == 0) break;
    content.append(buffer.data(), static_cast<std::size_t>(n));
  }
  if (gzclose(file) != Z_OK) throw std::runtime_error(path.string() + ": truncated gzip data");
  return content;
}

LaserLog read_carmen_file(const std::filesystem::path& path, const SensorOverrides& overrides) {
  return parse_carmen(read_maybe_gzipped(path), path.string(), overrides);
}

}  // namespace antslam::frontend
