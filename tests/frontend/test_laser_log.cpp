#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "antslam/frontend/laser_log.hpp"

namespace antslam::frontend {
namespace {

constexpr double kPi = std::numbers::pi;

std::string flaser(int n, double range) {
  std::string line = "FLASER ";
  line += std::to_string(n);
  for (int k = 0; k < n; ++k) {
    line += ' ';
    line += std::to_string(range);
  }
  line += " 1 2 0.5 1 2 0.5 10.5 host 10.6\n";
  return line;
}

void expect_error(const std::string& text, const std::string& message) {
  try {
    parse_carmen(text, "bad.clf");
    FAIL() << "expected an error for: " << text;
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
}

TEST(LaserLog, ReadsFlaserWithDefaultGeometry) {
  const LaserLog log = parse_carmen("# comment\n\n" + flaser(181, 2.5), "mem");
  ASSERT_EQ(log.scans.size(), 1U);
  const LaserScan& s = log.scans[0];
  EXPECT_EQ(s.ranges.size(), 181U);
  EXPECT_FLOAT_EQ(s.ranges[7], 2.5F);
  EXPECT_DOUBLE_EQ(s.stamp, 10.5);
  EXPECT_DOUBLE_EQ(s.odometry.x, 1.0);
  EXPECT_DOUBLE_EQ(s.odometry.theta, 0.5);
  // 180 degrees from -90 degrees, evenly spaced: beam 90 looks straight ahead.
  EXPECT_NEAR(s.beam_angle(0), -kPi / 2, 1e-12);
  EXPECT_NEAR(s.beam_angle(90), 0.0, 1e-12);
  EXPECT_NEAR(s.beam_angle(180), kPi / 2, 1e-12);
  EXPECT_DOUBLE_EQ(s.max_range, 80.0);
  EXPECT_DOUBLE_EQ(s.laser_pose.x, 0.0);
}

TEST(LaserLog, ParamLinesSetTheGeometryAndOverridesWin) {
  const std::string text =
      "PARAM laser_front_laser_fov 100 nohost 0\nPARAM robot_front_laser_max 50\n"
      "PARAM robot_frontlaser_offset 0.25 nohost 0\n" +
      flaser(11, 1.0);
  const LaserLog log = parse_carmen(text, "mem");
  const LaserScan& s = log.scans[0];
  EXPECT_NEAR(s.beam_angle(0), -50.0 * kPi / 180.0, 1e-12);
  EXPECT_NEAR(s.angle_step, 10.0 * kPi / 180.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.max_range, 50.0);
  EXPECT_DOUBLE_EQ(s.laser_pose.x, 0.25);
  // A field of view written in radians is recognised.
  EXPECT_NEAR(parse_carmen("PARAM laser_front_laser_fov 3.14159\n" + flaser(3, 1.0), "mem")
                  .scans[0]
                  .angle_step,
              3.14159 / 2.0, 1e-12);

  SensorOverrides o;
  o.field_of_view = kPi;
  o.first_angle = -1.0;
  o.max_range = 20.0;
  o.laser_offset = 0.78;
  const LaserScan t = parse_carmen(text, "mem", o).scans[0];
  EXPECT_DOUBLE_EQ(t.first_angle, -1.0);
  EXPECT_NEAR(t.angle_step, kPi / 10.0, 1e-12);
  EXPECT_DOUBLE_EQ(t.max_range, 20.0);
  EXPECT_DOUBLE_EQ(t.laser_pose.x, 0.78);
}

TEST(LaserLog, ReadsRobotLaser1AndOdom) {
  // type start fov res maxrange accuracy mode n r.. m v.. laser(3) robot(3) tv rv fsd ssd turn ts
  const std::string text =
      "ROBOTLASER1 0 -1.5 3.0 0.75 30 0.01 0 5 1 2 3 4 5 2 9 9 "
      "0.99750208 2.04991671 0.1 0.5 2.0 0.1 0 0 0 0 0 7.25 host 7.3\n"
      "ODOM 3 4 -0.2 0.1 0 0 8.5 host 8.6\nSYNC 1 2\n";
  const LaserLog log = parse_carmen(text, "mem");
  ASSERT_EQ(log.scans.size(), 1U);
  const LaserScan& s = log.scans[0];
  EXPECT_EQ(s.ranges.size(), 5U);
  EXPECT_DOUBLE_EQ(s.first_angle, -1.5);
  EXPECT_DOUBLE_EQ(s.angle_step, 0.75);
  EXPECT_DOUBLE_EQ(s.max_range, 30.0);
  EXPECT_DOUBLE_EQ(s.stamp, 7.25);
  EXPECT_DOUBLE_EQ(s.odometry.x, 0.5);
  // The laser sits 0.5 m ahead of the robot (both headings 0.1).
  EXPECT_NEAR(s.laser_pose.x, 0.5, 1e-8);
  EXPECT_NEAR(s.laser_pose.y, 0.0, 1e-8);
  EXPECT_NEAR(s.laser_pose.theta, 0.0, 1e-12);
  ASSERT_EQ(log.odometry.size(), 1U);
  EXPECT_DOUBLE_EQ(log.odometry[0].stamp, 8.5);
  EXPECT_NEAR(log.odometry[0].pose.theta, -0.2, 1e-12);
  EXPECT_EQ(log.skipped_messages, 1U);
}

TEST(LaserLog, MalformedLinesNameFileLineAndProblem) {
  expect_error("FLASER 3 1 2\n",
               "bad.clf:1: FLASER has 4 fields, expected at least 12 "
               "(FLASER n ranges x y theta odom_x odom_y odom_theta timestamp)");
  std::string two = "\n";
  two += flaser(3, 1.0);
  two += "FLASER x\n";
  expect_error(two, "bad.clf:3: number of readings 'x' is not a count");
  expect_error("FLASER 3 1 abc 3 0 0 0 0 0 0 1\n", "bad.clf:1: range 1 'abc' is not a number");
  expect_error("FLASER 3 1 -2 3 0 0 0 0 0 0 1\n", "bad.clf:1: range 1 is negative");
  expect_error("FLASER 3 1 nan 3 0 0 0 0 0 0 1\n", "bad.clf:1: range 1 is not finite");
  expect_error("FLASER 3 1 2 3 0 0 0 0 0 0 1 h 2 extra\n",
               "bad.clf:1: FLASER has 15 fields, expected at most 14");
  expect_error("ODOM 1 2\n",
               "bad.clf:1: ODOM has 3 fields, expected at least 8 (ODOM x y theta "
               "tv rv accel timestamp)");
  expect_error("PARAM robot_front_laser_max -3\n" + flaser(3, 1.0),
               "bad.clf:1: PARAM robot_front_laser_max: maximum range -3 m is not in (0, 1000 m]");
  expect_error("FLASER 3 1 1e39 3 0 0 0 0 0 0 1\n",
               "bad.clf:1: range 1 1e+39 m is beyond 3.40282e+38 m");
  expect_error("FLASER 3 1 2 3 0 0 0 1e10 0 0 1\n",
               "bad.clf:1: odometry 1e+10 m is beyond 1e+09 m");
  expect_error("FLASER 3 1 2 3 0 0 0 0 0 0 1e13\n",
               "bad.clf:1: timestamp 1e+13 s is beyond 1e+12 s");
  expect_error("hello world\n", "bad.clf:1: not a CARMEN message: 'hello'");
  expect_error("# only comments\nSYNC 1\n", "bad.clf: no FLASER or ROBOTLASER1 scans");
}

TEST(LaserLog, ChecksTheGeometryOfFileAndOverridesAlike) {
  // A laser offset of 1e308 m made the scan matcher's grid index overflow (SIGSEGV), a field of
  // view of 1e308 degrees became inf and hung the frontend: each is now one line naming the
  // PARAM line, and the same check refuses the same value as an override.
  const std::pair<std::string, std::string> params[] = {
      {"PARAM robot_frontlaser_offset 1e308\n",
       "bad.clf:1: PARAM robot_frontlaser_offset: laser offset 1e+308 m: the laser must be within "
       "10 m of the robot origin"},
      {"# c\nPARAM laser_front_laser_fov 1e308\n",
       "bad.clf:2: PARAM laser_front_laser_fov: field of view 1e+308 degrees is not in (0, 360] "
       "degrees"},
      {"PARAM laser_front_laser_fov 400\n",
       "bad.clf:1: PARAM laser_front_laser_fov: field of view 400 degrees is not in (0, 360] "
       "degrees"},
      {"PARAM robot_front_laser_max 1e6\n",
       "bad.clf:1: PARAM robot_front_laser_max: maximum range 1e+06 m is not in (0, 1000 m]"}};
  for (const auto& [param, message] : params) expect_error(param + flaser(3, 1.0), message);
  // ROBOTLASER1 lines carry their own geometry: 5 beams 2 rad apart span 8 rad; a maximum range
  // of 0; a laser 50 m from the robot.
  const std::string tail = " 0.01 0 5 1 2 3 4 5 0 ";
  const std::string zeros = " 0 0 0 0 0 0 0 0 0 0 7.25\n";
  expect_error("ROBOTLASER1 0 -1.5 3.0 2.0 30" + tail + "0" + zeros,
               "bad.clf:1: ROBOTLASER1 field of view 458.366 degrees is not in (0, 360] degrees");
  expect_error("ROBOTLASER1 0 -1.5 3.0 0.75 0" + tail + "0" + zeros,
               "bad.clf:1: ROBOTLASER1 maximum range 0 m is not in (0, 1000 m]");
  expect_error("ROBOTLASER1 0 -1.5 3.0 0.75 30" + tail + "50" + zeros,
               "bad.clf:1: ROBOTLASER1 laser offset 50 m: the laser must be within 10 m of the "
               "robot origin");
  // An override wins over the log, so it may repair a bad PARAM value.
  SensorOverrides repaired;
  repaired.laser_offset = 0.5;
  EXPECT_DOUBLE_EQ(
      parse_carmen("PARAM robot_frontlaser_offset 1e308\n" + flaser(3, 1.0), "mem", repaired)
          .scans[0]
          .laser_pose.x,
      0.5);
  for (const double offset : {1e308, -11.0}) {
    SensorOverrides o;
    o.laser_offset = offset;
    EXPECT_THROW(parse_carmen(flaser(3, 1.0), "mem", o), std::invalid_argument);
  }
  EXPECT_EQ(laser_offset_problem(-10.0), "");
  EXPECT_EQ(field_of_view_problem(2.0 * kPi), "");
  EXPECT_NE(field_of_view_problem(std::numeric_limits<double>::infinity()), "");
  EXPECT_NE(first_angle_problem(std::nan("")), "");
  EXPECT_NE(max_range_problem(std::nan("")), "");
}

TEST(LaserLog, TimeOrderIsCheckedOnRequest) {
  // Writing the odometry of such a log gave a TUM file that antslam eval refused.
  const std::string text = flaser(3, 1.0) + "FLASER 3 1 1 1 0 0 0 0 0 0 0.5\n";
  const LaserLog log = parse_carmen(text, "t.clf");
  try {
    require_time_order(log);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(),
                 "t.clf:2: scan timestamp 0.5 s is earlier than 10.5 s on line 1 (a TUM "
                 "trajectory needs the scans in time order)");
  }
  EXPECT_NO_THROW(require_time_order(parse_carmen(flaser(3, 1.0) + flaser(3, 2.0), "same.clf")));
}

TEST(LaserLog, RejectsNonsenseOverrides) {
  SensorOverrides o;
  o.field_of_view = 0.0;
  EXPECT_THROW(parse_carmen(flaser(3, 1.0), "mem", o), std::invalid_argument);
  o = {};
  o.max_range = -1.0;
  EXPECT_THROW(parse_carmen(flaser(3, 1.0), "mem", o), std::invalid_argument);
}

TEST(LaserLog, ReadsGzipAndPlainFilesAlike) {
  const std::filesystem::path dir = ANTSLAM_TEST_TMP;
  std::filesystem::create_directories(dir);
  const std::string text = "PARAM robot_front_laser_max 40\n" + flaser(5, 3.0) + flaser(5, 4.0);
  {
    std::ofstream plain(dir / "log.clf");
    plain << text;
  }
  gzFile gz = gzopen((dir / "log.clf.gz").c_str(), "wb");
  ASSERT_NE(gz, nullptr);
  ASSERT_EQ(gzwrite(gz, text.data(), static_cast<unsigned>(text.size())),
            static_cast<int>(text.size()));
  gzclose(gz);
  const LaserLog a = read_carmen_file(dir / "log.clf");
  const LaserLog b = read_carmen_file(dir / "log.clf.gz");
  ASSERT_EQ(b.scans.size(), 2U);
  EXPECT_EQ(a.scans[1].ranges, b.scans[1].ranges);
  EXPECT_DOUBLE_EQ(b.scans[1].max_range, 40.0);
  EXPECT_THROW(read_carmen_file(dir / "missing.clf"), std::runtime_error);
  EXPECT_THROW(read_carmen_file(dir), std::runtime_error);
  // A damaged gzip stream is an error, not a silently short log.
  std::ifstream in(dir / "log.clf.gz", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream cut(dir / "cut.clf.gz", std::ios::binary);
  cut << bytes.substr(0, bytes.size() - 12);
  cut.close();
  EXPECT_THROW(read_carmen_file(dir / "cut.clf.gz"), std::runtime_error);
}

TEST(LaserLog, ReadsTheBundledMalagaLog) {
  SensorOverrides o;
  o.laser_offset = 0.78;
  const LaserLog log = read_carmen_file(ANTSLAM_DATA_DIR "/laser/malaga-oneloop.clf", o);
  ASSERT_EQ(log.scans.size(), 225U);
  EXPECT_EQ(log.scans[0].ranges.size(), 361U);
  EXPECT_NEAR(log.scans[0].angle_step, kPi / 360.0, 1e-12);
  EXPECT_DOUBLE_EQ(log.scans[0].laser_pose.x, 0.78);
  EXPECT_FLOAT_EQ(log.scans[0].ranges[0], 1.69F);
}

}  // namespace
}  // namespace antslam::frontend
