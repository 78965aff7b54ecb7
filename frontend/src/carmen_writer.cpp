#include "antslam/frontend/carmen_writer.hpp"

#include <charconv>
#include <cmath>
#include <numbers>
#include <ostream>
#include <stdexcept>
#include <system_error>

namespace antslam::frontend {

namespace {

/// Writes numbers in the shortest form that reads back to the same value.
class NumberWriter {
 public:
  explicit NumberWriter(std::ostream& out) : out_(out) {}

  void put(double value) {
    const auto [end, ec] = std::to_chars(buffer_, buffer_ + sizeof buffer_, value);
    out_ << ' ';
    out_.write(buffer_, end - buffer_);
  }

  /// The reader parses ranges as doubles and rounds them to float: the float's own shortest
  /// form survives that double rounding almost always; where it does not, the exact double is
  /// written instead.
  void put(float value) {
    const auto [end, ec] = std::to_chars(buffer_, buffer_ + sizeof buffer_, value);
    double read = 0.0;
    std::from_chars(buffer_, end, read);
    if (static_cast<float>(read) != value) return put(static_cast<double>(value));
    out_ << ' ';
    out_.write(buffer_, end - buffer_);
  }

  void put(const slam::Pose2& p) {
    put(p.x);
    put(p.y);
    put(p.theta);
  }

 private:
  std::ostream& out_;
  char buffer_[64]{};
};

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument(what); }

bool close(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b)); }

bool finite(const slam::Pose2& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.theta);
}

void check_geometry(const SensorGeometry& g) {
  const double fov = g.field_of_view;
  if (!(fov > 0.0 && fov <= 2.0 * std::numbers::pi)) fail("field of view must be in (0, 2 pi]");
  if (g.first_angle && !close(*g.first_angle, -0.5 * fov))
    fail("first beam angle must be -fov/2 in a FLASER log");
  if (!(g.max_range > 0.0 && std::isfinite(g.max_range)))
    fail("maximum range must be a positive number");
  if (!std::isfinite(g.laser_pose.x) || g.laser_pose.y != 0.0 || g.laser_pose.theta != 0.0)
    fail("a FLASER log can only hold a laser on the robot's x axis, facing forward");
}

void check_scan(const LaserScan& scan, std::size_t index, const SensorGeometry& g) {
  const std::string name = "scan " + std::to_string(index) + ": ";
  const std::size_t n = scan.ranges.size();
  if (n < 2) fail(name + "FLASER needs at least 2 readings");
  const double step = g.field_of_view / static_cast<double>(n - 1);
  if (!close(scan.first_angle, -0.5 * g.field_of_view) || !close(scan.angle_step, step) ||
      scan.max_range != g.max_range || scan.laser_pose.x != g.laser_pose.x ||
      scan.laser_pose.y != 0.0 || scan.laser_pose.theta != 0.0)
    fail(name + "geometry differs from the log's FLASER geometry");
  if (!std::isfinite(scan.stamp)) fail(name + "timestamp is not finite");
  if (!finite(scan.odometry)) fail(name + "odometry is not finite");
  for (std::size_t k = 0; k < n; ++k)
    if (!(scan.ranges[k] >= 0.0F && std::isfinite(scan.ranges[k])))
      fail(name + "range " + std::to_string(k) + " is negative or not finite");
}

void write_param(std::ostream& out, const char* name, double value) {
  out << "PARAM " << name;
  NumberWriter(out).put(value);
  out << " 0 antslam 0\n";
}

// FLASER n r_1..r_n x y theta odom_x odom_y odom_theta timestamp host logger_timestamp
void write_flaser(std::ostream& out, const LaserScan& scan) {
  NumberWriter number(out);
  out << "FLASER " << scan.ranges.size();
  for (const float r : scan.ranges) number.put(r);
  number.put(scan.odometry);
  number.put(scan.odometry);
  number.put(scan.stamp);
  out << " antslam";
  number.put(scan.stamp);
  out << '\n';
}

// ODOM x y theta tv rv accel timestamp host logger_timestamp
void write_odom(std::ostream& out, const slam::StampedPose& odom, std::size_t index) {
  if (!finite(odom.pose) || !std::isfinite(odom.stamp))
    fail("odometry message " + std::to_string(index) + " is not finite");
  NumberWriter number(out);
  out << "ODOM";
  number.put(odom.pose);
  out << " 0 0 0";
  number.put(odom.stamp);
  out << " antslam";
  number.put(odom.stamp);
  out << '\n';
}

}  // namespace

void write_carmen(std::ostream& out, const LaserLog& log, std::span<const std::string> comments) {
  const SensorGeometry& g = log.flaser_geometry;
  check_geometry(g);
  for (std::size_t i = 0; i < log.scans.size(); ++i) check_scan(log.scans[i], i, g);
  for (const std::string& c : comments) {
    if (c.find_first_of("\r\n") != std::string::npos) fail("a comment holds a line break");
    out << "# " << c << '\n';
  }
  // CARMEN writes the field of view in degrees; the reader takes values up to 2 pi as radians,
  // so a field of view under 2 pi degrees stays in radians.
  const double degrees = g.field_of_view * 180.0 / std::numbers::pi;
  write_param(out, "laser_front_laser_fov",
              degrees > 2.0 * std::numbers::pi + 1e-6 ? degrees : g.field_of_view);
  write_param(out, "robot_front_laser_max", g.max_range);
  write_param(out, "robot_frontlaser_offset", g.laser_pose.x);
  std::size_t s = 0, o = 0;
  while (s < log.scans.size() || o < log.odometry.size()) {
    if (o < log.odometry.size() &&
        (s == log.scans.size() || log.odometry[o].stamp < log.scans[s].stamp)) {
      write_odom(out, log.odometry[o], o);
      ++o;
    } else {
      write_flaser(out, log.scans[s++]);
    }
  }
  if (!out) throw std::runtime_error("writing the CARMEN log failed");
}

}  // namespace antslam::frontend
