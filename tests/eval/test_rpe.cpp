#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "antslam/eval/alignment.hpp"
#include "antslam/eval/relative_error.hpp"
#include "antslam/eval/rpe.hpp"
#include "trajectories.hpp"

namespace antslam::eval {
namespace {

using testing::make_trajectory;

std::vector<PosePair> pairs_of(const slam::Trajectory& estimate,
                               const slam::Trajectory& reference) {
  return associate(estimate, reference, 0.0);
}

// Reference: one metre steps along x, heading 0.
const slam::Trajectory kLine =
    make_trajectory({{0, 0, 0, 0}, {1, 1, 0, 0}, {2, 2, 0, 0}, {3, 3, 0, 0}});

TEST(RelativeError, HandComputed) {
  // Estimated motion (1, 0, 0.1) against reference (1, 0, 0): no translation error, 0.1 rad.
  const RelativeError a = relative_error({1, 0, 0}, {2, 0, 0.1}, {1, 0, 0});
  EXPECT_NEAR(a.translation, 0.0, 1e-12);
  EXPECT_NEAR(a.rotation, 0.1, 1e-12);
  // From (2, 0, 0.1) to (3, 0, 0): motion (cos 0.1, -sin 0.1, -0.1); against (1, 0, 0) the
  // translation differs by sqrt((1 - cos 0.1)^2 + sin^2 0.1) = 2 sin 0.05.
  const RelativeError b = relative_error({2, 0, 0.1}, {3, 0, 0}, {1, 0, 0});
  EXPECT_NEAR(b.translation, 2.0 * std::sin(0.05), 1e-12);
  EXPECT_NEAR(b.rotation, 0.1, 1e-12);
  EXPECT_NEAR(degrees(std::numbers::pi), 180.0, 1e-12);
}

TEST(Rpe, FrameStepHandComputed) {
  // Pose 2 drifted 0.1 m forward, the rest exact: steps 0->1, 1->2, 2->3 err 0, 0.1, 0.1.
  const slam::Trajectory estimate =
      make_trajectory({{0, 0, 0, 0}, {1, 1, 0, 0}, {2, 2.1, 0, 0}, {3, 3.0, 0, 0}});
  const RpeResult one = rpe(pairs_of(estimate, kLine), {.frames = 1});
  EXPECT_EQ(one.translation_m.count, 3U);
  EXPECT_NEAR(one.translation_m.mean, 0.2 / 3.0, 1e-12);
  EXPECT_NEAR(one.translation_m.rmse, std::sqrt(0.02 / 3.0), 1e-12);
  EXPECT_NEAR(one.rotation_deg.max, 0.0, 1e-12);
  // Two frames: 0->2 err 0.1, 1->3 err 0.
  const RpeResult two = rpe(pairs_of(estimate, kLine), {.frames = 2});
  EXPECT_EQ(two.translation_m.count, 2U);
  EXPECT_NEAR(two.translation_m.mean, 0.05, 1e-12);
  EXPECT_NEAR(two.translation_m.max, 0.1, 1e-12);
}

TEST(Rpe, HeadingErrorHandComputed) {
  // Pose 2 turned by 0.1 rad: step 1->2 errs (0 m, 0.1 rad), step 2->3 (2 sin 0.05 m, 0.1 rad).
  const slam::Trajectory estimate =
      make_trajectory({{0, 0, 0, 0}, {1, 1, 0, 0}, {2, 2, 0, 0.1}, {3, 3, 0, 0}});
  const RpeResult r = rpe(pairs_of(estimate, kLine), {.frames = 1});
  const double e = 2.0 * std::sin(0.05);
  EXPECT_NEAR(r.translation_m.mean, e / 3.0, 1e-12);
  EXPECT_NEAR(r.translation_m.rmse, e / std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(r.rotation_deg.mean, degrees(0.2) / 3.0, 1e-9);
  EXPECT_NEAR(r.rotation_deg.rmse, degrees(0.1) * std::sqrt(2.0 / 3.0), 1e-9);
}

TEST(Rpe, DistanceStepHandComputed) {
  // Reference travelled 0, 0.5, 1.5, 1.6, 3.0 m; step 1 m pairs 0->2, 1->2, 2->4, 3->4.
  const slam::Trajectory reference = make_trajectory(
      {{0, 0, 0, 0}, {1, 0.5, 0, 0}, {2, 1.5, 0, 0}, {3, 1.6, 0, 0}, {4, 3.0, 0, 0}});
  slam::Trajectory estimate = reference;
  estimate[4].pose.x = 3.2;  // the last two pairs err by 0.2 m
  const RpeResult r = rpe(pairs_of(estimate, reference), {.metres = 1.0});
  EXPECT_EQ(r.translation_m.count, 4U);
  EXPECT_NEAR(r.translation_m.mean, 0.1, 1e-12);
  EXPECT_NEAR(r.translation_m.rmse, std::sqrt(0.02), 1e-12);
  EXPECT_NEAR(r.translation_m.median, 0.1, 1e-12);
  // A step of 2 m leaves only 0->4 (3 m) and 1->4 (2.5 m).
  EXPECT_EQ(rpe(pairs_of(estimate, reference), {.metres = 2.0}).translation_m.count, 2U);
}

TEST(Rpe, DoesNotDependOnARigidTransformOfTheEstimate) {
  const slam::Trajectory reference = testing::spiral(30);
  const auto pairs = pairs_of(transformed(reference, {5.0, -1.0, 2.0}), reference);
  for (const RpeSettings s :
       {RpeSettings{.frames = 1}, RpeSettings{.frames = 7}, RpeSettings{.metres = 2.5}}) {
    const RpeResult r = rpe(pairs, s);
    EXPECT_LT(r.translation_m.max, 1e-9);
    EXPECT_LT(r.rotation_deg.max, 1e-7);
  }
}

TEST(Rpe, RejectsBadStepsAndStepsLongerThanTheTrajectory) {
  const auto pairs = pairs_of(kLine, kLine);
  EXPECT_THROW(rpe(pairs, {.frames = 0}), std::invalid_argument);
  EXPECT_THROW(rpe(pairs, {.metres = -1.0}), std::invalid_argument);
  EXPECT_THROW(rpe(pairs, {.metres = std::numeric_limits<double>::quiet_NaN()}),
               std::invalid_argument);
  try {
    rpe(pairs, {.frames = 4});
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "RPE: no two of the 4 associated poses are 4 frames apart");
  }
  EXPECT_THROW(rpe(pairs, {.metres = 3.5}), std::invalid_argument);
  EXPECT_EQ(rpe(pairs, {.metres = 3.0}).translation_m.count, 1U);
}

}  // namespace
}  // namespace antslam::eval
