#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "antslam/slamgraph/trajectory.hpp"

namespace antslam::slam {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Tum, RoundTrip) {
  const Trajectory t{{1134864642.914187, Pose2{0.154, 0.068, 0.5623}},
                     {1134864643.553180, Pose2{-3.5, 2.25, -2.9}}};
  std::stringstream s;
  write_tum(s, t);
  const Trajectory back = read_tum(s, "mem");
  ASSERT_EQ(back.size(), 2U);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(back[i].stamp, t[i].stamp, 1e-6);
    EXPECT_NEAR(back[i].pose.x, t[i].pose.x, 1e-9);
    EXPECT_NEAR(back[i].pose.y, t[i].pose.y, 1e-9);
    EXPECT_NEAR(back[i].pose.theta, t[i].pose.theta, 1e-8);
  }
}

TEST(Tum, ReadsTheReferenceFormat) {
  std::istringstream s(
      "# comment\n1134864642.914187 0.154000 0.068000 0 0 0 0.277666751 0.960677456\n");
  const Trajectory t = read_tum(s, "ref");
  ASSERT_EQ(t.size(), 1U);
  EXPECT_NEAR(t[0].pose.theta, 2.0 * std::atan2(0.277666751, 0.960677456), 1e-8);
}

void expect_error(const std::string& text, const std::string& message) {
  std::istringstream s(text);
  try {
    read_tum(s, "bad.tum");
    FAIL() << "expected an error for: " << text;
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
}

TEST(Tum, RejectsMalformedLinesWithFileAndLine) {
  expect_error("1 2 3 4 5 6 7\n", "bad.tum:1: expected 8 numbers `timestamp x y z qx qy qz qw`");
  expect_error("# c\n1 2 3 4 5 6 7 x\n", "bad.tum:2: 'x' is not a number");
  expect_error("1 nan 0 0 0 0 0 1\n", "bad.tum:1: non-finite number");
  expect_error("1 0 0 0 0 0 0 inf\n", "bad.tum:1: non-finite number");
  expect_error("1 0 0 0 0 0 0 0\n",
               "bad.tum:1: quaternion (0, 0, 0, 0) has norm 0, not 1 (a rotation's quaternion is "
               "a unit quaternion)");
  expect_error("1 0 0 0 0 0 1.41421356 1.41421356\n",
               "bad.tum:1: quaternion (0, 0, 1.41421, 1.41421) has norm 2, not 1 (a rotation's "
               "quaternion is a unit quaternion)");
  // Overflowing values: their squares would make the metrics inf.
  expect_error("0 0 0 0 0 0 0 1\n1 1e160 0 0 0 0 0 1\n",
               "bad.tum:2: position (1e+160, 0, 0) m is beyond 1e+09 m");
  expect_error("1e300 0 0 0 0 0 0 1\n", "bad.tum:1: timestamp 1e+300 s is beyond 1e+12 s");
  expect_error("1 0 0 1e400 0 0 0 1\n", "bad.tum:1: '1e400' is not a number");
  expect_error("2 0 0 0 0 0 0 1\n1 0 0 0 0 0 0 1\n", "bad.tum:2: timestamp decreases");
  expect_error("1 0 0 0 0 0 0 1 9\n", "bad.tum:1: unexpected extra field '9'");
}

TEST(Tum, NormalisesQuaternionsThatMissOneByRounding) {
  // The same 90 degree yaw as a unit quaternion, one 0.5 % too long, and one with roll/pitch
  // parts zero: the yaw of q v q* / |q|^2 does not depend on |q|.
  std::istringstream s(
      "0 0 0 0 0 0 0.7071067811865476 0.7071067811865476\n"
      "1 0 0 0 0 0 0.7106423 0.7106423\n");
  const Trajectory t = read_tum(s, "q.tum");
  ASSERT_EQ(t.size(), 2U);
  EXPECT_NEAR(t[0].pose.theta, kPi / 2.0, 1e-12);
  EXPECT_NEAR(t[1].pose.theta, kPi / 2.0, 1e-12);
}

TEST(Tum, WriterRefusesWhatTheReaderRefuses) {
  const auto refused = [](const Trajectory& t) {
    std::ostringstream out;
    try {
      write_tum(out, t);
    } catch (const std::invalid_argument& e) {
      EXPECT_TRUE(out.str().empty());  // nothing half-written
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(refused({{2.0, {0, 0, 0}}, {1.0, {0, 0, 0}}}),
            "TUM trajectory: timestamps decrease at pose 1 (TUM files need them in time order)");
  EXPECT_EQ(refused({{0.0, {1e10, 0, 0}}}),
            "TUM trajectory: pose 0: position (1e+10, 0, 0) m is beyond 1e+09 m");
  EXPECT_EQ(refused({{0.0, {0, std::nan(""), 0}}}), "TUM trajectory: pose 0: non-finite number");
  EXPECT_EQ(refused({{1.0, {0, 0, 0}}, {1.0, {1, 0, 0}}}), "");  // equal stamps are fine
}

TEST(Trajectory, PathLengthByHand) {
  const Trajectory t{{0.0, {0, 0, 0}}, {1.0, {3, 4, 1}}, {2.0, {3, 4, -2}}, {3.0, {3, 1, 0}}};
  EXPECT_DOUBLE_EQ(path_length(t), 5.0 + 0.0 + 3.0);
  EXPECT_EQ(path_length(Trajectory{}), 0.0);
  EXPECT_EQ(path_length(Trajectory{{0.0, {7, 7, 0}}}), 0.0);
}

}  // namespace
}  // namespace antslam::slam
