#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "antslam/eval/relations.hpp"
#include "antslam/eval/relations_error.hpp"
#include "antslam/eval/relative_error.hpp"
#include "trajectories.hpp"

namespace antslam::eval {
namespace {

constexpr double kHalfPi = std::numbers::pi / 2.0;

std::vector<Relation> parse(const std::string& text) {
  std::istringstream in(text);
  return read_relations(in, "test.relations");
}

void expect_error(const std::string& text, const std::string& message) {
  try {
    parse(text);
    FAIL() << "expected an error for: " << text;
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
}

TEST(ReadRelations, ReadsLinesSkippingCommentsAndBlanks) {
  const auto r = parse(
      "# t1 t2 dx dy dz droll dpitch dyaw\n\n"
      "976052905.167303 976052911.885496 -0.056990 -0.128430 0.000000 0.000000 0.000000 "
      "-1.682210\n"
      "  1 2 0.5 0.25 0 0 0 4.0\r\n");
  ASSERT_EQ(r.size(), 2U);
  EXPECT_DOUBLE_EQ(r[0].stamp1, 976052905.167303);
  EXPECT_DOUBLE_EQ(r[0].stamp2, 976052911.885496);
  EXPECT_DOUBLE_EQ(r[0].motion.x, -0.056990);
  EXPECT_DOUBLE_EQ(r[0].motion.y, -0.128430);
  EXPECT_DOUBLE_EQ(r[0].motion.theta, -1.682210);
  EXPECT_EQ(r[0].line, 3U);
  EXPECT_NEAR(r[1].motion.theta, 4.0 - 2.0 * std::numbers::pi, 1e-12);  // wrapped
  EXPECT_EQ(r[1].line, 4U);
}

TEST(ReadRelations, RejectsMalformedLinesWithFileAndLine) {
  const std::string format = "expected 8 numbers `t1 t2 dx dy dz droll dpitch dyaw`";
  expect_error("1 2 0 0 0 0 0\n", "test.relations:1: " + format);
  expect_error("# c\n1 2 0 0 0 0 0 x\n", "test.relations:2: " + format);
  expect_error("1 2 0.1.2 0 0 0 0 0\n", "test.relations:1: " + format);
  expect_error("1 2 0 nan 0 0 0 0\n", "test.relations:1: non-finite number 'nan'");
  expect_error("1 2 0 0 0 0 0 inf\n", "test.relations:1: non-finite number 'inf'");
  expect_error("1 2 0 0 0 0 0 0 9\n", "test.relations:1: unexpected extra field '9'");
  expect_error("1 2 0 0 0 0.1 0 0\n",
               "test.relations:1: dz, droll and dpitch must be 0 in a 2D relation");
  expect_error("# only a comment\n\n", "test.relations: no relations");
}

TEST(ReadRelations, MissingFileIsNamed) {
  try {
    read_relations_file("no/such/file.relations");
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "no/such/file.relations: cannot open");
  }
}

TEST(RelationsError, HandComputed) {
  // Estimate: origin; (1, 0) facing +y; (1, 1) facing +y.
  const slam::Trajectory estimate =
      testing::make_trajectory({{1.0, 0, 0, 0}, {2.0, 1, 0, kHalfPi}, {3.0, 1, 1, kHalfPi}});
  const auto relations = parse(
      // exact: estimated motion 1 -> 2 is (1, 0, pi/2)         errors 0 m,   0 rad
      "1 2 1 0 0 0 0 1.5707963267948966\n"
      // estimated 2 -> 3 is (1, 0, 0); relation (1.1, 0, 0.05)  errors 0.1 m, 0.05 rad
      "2 3 1.1 0 0 0 0 0.05\n"
      // estimated 1 -> 3 is (1, 1, pi/2); relation (1, 1.2, pi/2 + 0.1): 0.2 m, 0.1 rad
      "1 3 1 1.2 0 0 0 1.6707963267948966\n"
      // t2 = 7.5 is not in the estimate: skipped
      "1 7.5 0 0 0 0 0 0\n"
      // backwards, stamps 15 and 5 ms off: estimated 3 -> 1 is (-1, 1, -pi/2), exact: 0 m, 0 rad
      "3.015 1.005 -1 1 0 0 0 -1.5707963267948966\n");
  const RelationsResult r = relations_error(estimate, relations, 0.02);
  EXPECT_EQ(r.used, 4U);
  EXPECT_EQ(r.skipped, 1U);
  // translation {0, 0.1, 0.2, 0}: mean 0.075, squared deviations sum 0.0275, n - 1 = 3
  EXPECT_NEAR(r.translation_m.mean, 0.075, 1e-12);
  EXPECT_NEAR(r.translation_m.std, std::sqrt(0.0275 / 3.0), 1e-12);
  // squared {0, 0.01, 0.04, 0}: mean 0.0125, squared deviations sum 0.001075
  EXPECT_NEAR(r.translation_squared_m2.mean, 0.0125, 1e-12);
  EXPECT_NEAR(r.translation_squared_m2.std, std::sqrt(0.001075 / 3.0), 1e-12);
  // rotation {0, 0.05, 0.1, 0} rad, reported in degrees
  const double d = degrees(0.05);
  EXPECT_NEAR(r.rotation_deg.mean, 3.0 * d / 4.0, 1e-9);
  EXPECT_NEAR(r.rotation_deg.std, d * std::sqrt(2.75 / 3.0),
              1e-9);  // deviations -.75 .25 1.25 -.75
  EXPECT_NEAR(r.rotation_squared_deg2.mean, 5.0 * d * d / 4.0, 1e-9);  // {0, d^2, 4 d^2, 0}
  // With a 10 ms tolerance the backwards relation no longer matches.
  const RelationsResult tight = relations_error(estimate, relations, 0.01);
  EXPECT_EQ(tight.used, 3U);
  EXPECT_EQ(tight.skipped, 2U);
}

TEST(RelationsError, NothingToScoreIsAnError) {
  const slam::Trajectory estimate = testing::make_trajectory({{1.0, 0, 0, 0}, {2.0, 1, 0, 0}});
  const auto relations = parse("5 6 1 0 0 0 0 0\n");
  try {
    relations_error(estimate, relations, 0.02);
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "relations: none of the 1 relations has both stamps in the estimate within "
                 "max_dt = 0.02 s");
  }
  EXPECT_THROW(relations_error(estimate, relations, -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace antslam::eval
