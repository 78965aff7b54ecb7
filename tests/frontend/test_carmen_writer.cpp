#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "antslam/aco/random.hpp"
#include "antslam/frontend/carmen_writer.hpp"
#include "antslam/frontend/laser_log.hpp"

namespace antslam::frontend {
namespace {

std::string written(const LaserLog& log, const std::vector<std::string>& comments = {}) {
  std::ostringstream out;
  write_carmen(out, log, comments);
  return out.str();
}

/// A small log with the FLASER geometry given by the reader's defaults.
LaserLog small_log() {
  LaserLog log = parse_carmen(
      "FLASER 3 1 2.5 0.125 0 0 0 0.5 -1 0.25 10 h 10\n"
      "FLASER 3 4 5 6 0 0 0 1.5 -2 -3 11.5 h 11.5\n",
      "mem");
  log.odometry = {{9.0, {0.25, 0.5, 0.75}}, {11.0, {1.0, 2.0, 3.0}}, {12.0, {4.0, 5.0, -1.0}}};
  return log;
}

void expect_same(const LaserLog& a, const LaserLog& b) {
  ASSERT_EQ(a.scans.size(), b.scans.size());
  for (std::size_t i = 0; i < a.scans.size(); ++i) {
    const LaserScan &s = a.scans[i], &t = b.scans[i];
    EXPECT_EQ(s.ranges, t.ranges) << "scan " << i;
    EXPECT_EQ(s.stamp, t.stamp);
    EXPECT_EQ(s.odometry.x, t.odometry.x);
    EXPECT_EQ(s.odometry.y, t.odometry.y);
    EXPECT_NEAR(s.odometry.theta, t.odometry.theta, 1e-15);  // the reader wraps angles
    EXPECT_NEAR(s.first_angle, t.first_angle, 1e-14);
    EXPECT_NEAR(s.angle_step, t.angle_step, 1e-14);
    EXPECT_EQ(s.max_range, t.max_range);
    EXPECT_EQ(s.laser_pose.x, t.laser_pose.x);
  }
  ASSERT_EQ(a.odometry.size(), b.odometry.size());
  for (std::size_t i = 0; i < a.odometry.size(); ++i) {
    EXPECT_EQ(a.odometry[i].stamp, b.odometry[i].stamp);
    EXPECT_EQ(a.odometry[i].pose.x, b.odometry[i].pose.x);
    EXPECT_NEAR(a.odometry[i].pose.theta, b.odometry[i].pose.theta, 1e-15);
  }
}

TEST(CarmenWriter, WritesParamsThenMessagesInTimeOrder) {
  EXPECT_EQ(written(small_log(), {"made by a test"}),
            "# made by a test\n"
            "PARAM laser_front_laser_fov 180 0 antslam 0\n"
            "PARAM robot_front_laser_max 80 0 antslam 0\n"
            "PARAM robot_frontlaser_offset 0 0 antslam 0\n"
            "ODOM 0.25 0.5 0.75 0 0 0 9 antslam 9\n"
            "FLASER 3 1 2.5 0.125 0.5 -1 0.25 0.5 -1 0.25 10 antslam 10\n"
            "ODOM 1 2 3 0 0 0 11 antslam 11\n"
            "FLASER 3 4 5 6 1.5 -2 -3 1.5 -2 -3 11.5 antslam 11.5\n"
            "ODOM 4 5 -1 0 0 0 12 antslam 12\n");
}

TEST(CarmenWriter, SmallLogRoundTrips) {
  const LaserLog log = small_log();
  expect_same(log, parse_carmen(written(log), "mem"));
}

TEST(CarmenWriter, BundledLogRoundTripsWithItsGeometry) {
  SensorOverrides malaga;
  malaga.laser_offset = 0.78;
  malaga.max_range = 30.0;
  const LaserLog log =
      read_carmen_file(std::string(ANTSLAM_DATA_DIR) + "/laser/malaga-oneloop.clf", malaga);
  const LaserLog back = parse_carmen(written(log), "mem");
  expect_same(log, back);
  EXPECT_DOUBLE_EQ(back.flaser_geometry.laser_pose.x, 0.78);
  EXPECT_DOUBLE_EQ(back.flaser_geometry.max_range, 30.0);
}

TEST(CarmenWriter, EveryFloatRangeReadsBackExactly) {
  // The reader rounds a double to float: the written text must survive that for any range.
  LaserLog log = small_log();
  aco::Rng rng(5);
  LaserScan& scan = log.scans[0];
  scan.ranges.resize(20000);
  for (float& r : scan.ranges) {
    const auto bits = static_cast<std::uint32_t>(rng() >> 33U);  // positive finite floats
    r = std::bit_cast<float>(bits & 0x7F7FFFFFU);
  }
  scan.angle_step = scan.first_angle * -2.0 / static_cast<double>(scan.ranges.size() - 1);
  log.scans.resize(1);
  EXPECT_EQ(parse_carmen(written(log), "mem").scans[0].ranges, scan.ranges);
}

TEST(CarmenWriter, NarrowFieldOfViewStaysInRadians) {
  LaserLog log = small_log();
  log.flaser_geometry.field_of_view = 0.05;  // 2.9 degrees: the reader would read it as radians
  for (LaserScan& s : log.scans) {
    s.first_angle = -0.025;
    s.angle_step = 0.025;
  }
  EXPECT_NE(written(log).find("PARAM laser_front_laser_fov 0.05 "), std::string::npos);
  expect_same(log, parse_carmen(written(log), "mem"));
}

void expect_invalid(const LaserLog& log, const std::string& message,
                    const std::vector<std::string>& comments = {}) {
  try {
    written(log, comments);
    FAIL() << "expected: " << message;
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
}

TEST(CarmenWriter, RefusesWhatFlaserLinesCannotHold) {
  LaserLog log = small_log();
  log.scans[1].angle_step *= 0.5;
  expect_invalid(log, "scan 1: geometry differs from the log's FLASER geometry");
  log = small_log();
  log.scans[0].ranges[2] = std::numeric_limits<float>::quiet_NaN();
  expect_invalid(log, "scan 0: range 2 is negative or not finite");
  log = small_log();
  log.scans[1].ranges.resize(1);
  expect_invalid(log, "scan 1: FLASER needs at least 2 readings");
  log = small_log();
  log.flaser_geometry.laser_pose.theta = 0.1;
  expect_invalid(log, "a FLASER log can only hold a laser on the robot's x axis, facing forward");
  log = small_log();
  log.odometry[2].pose.x = INFINITY;
  expect_invalid(log, "odometry message 2 is not finite");
  expect_invalid(small_log(), "a comment holds a line break", {"two\nlines"});
}

}  // namespace
}  // namespace antslam::frontend
