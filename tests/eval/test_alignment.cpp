#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include "antslam/eval/alignment.hpp"
#include "antslam/eval/ate.hpp"
#include "trajectories.hpp"

namespace antslam::eval {
namespace {

using testing::spiral;

void expect_pose_near(const slam::Pose2& a, const slam::Pose2& b, double tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(slam::wrap_angle(a.theta - b.theta), 0.0, tol);
}

/// Brute-force least squares, independent of the library: for a fixed angle the best
/// translation is the mean of r_i - R e_i; the angle is searched on a grid, then on finer grids
/// around the best cell.
slam::Pose2 brute_force_alignment(const std::vector<PosePair>& pairs) {
  const auto with_angle = [&](double alpha) {
    const double c = std::cos(alpha), s = std::sin(alpha);
    double tx = 0.0, ty = 0.0;
    for (const PosePair& p : pairs) {
      tx += p.reference.x - (c * p.estimate.x - s * p.estimate.y);
      ty += p.reference.y - (s * p.estimate.x + c * p.estimate.y);
    }
    const double n = static_cast<double>(pairs.size());
    return slam::Pose2{tx / n, ty / n, alpha};
  };
  const auto cost = [&](double alpha) {
    const slam::Pose2 T = with_angle(alpha);
    const double c = std::cos(alpha), s = std::sin(alpha);
    double sum = 0.0;
    for (const PosePair& p : pairs) {
      const double dx = c * p.estimate.x - s * p.estimate.y + T.x - p.reference.x;
      const double dy = s * p.estimate.x + c * p.estimate.y + T.y - p.reference.y;
      sum += dx * dx + dy * dy;
    }
    return sum;
  };
  double step = 2.0 * std::numbers::pi / 3600.0;
  double best = -std::numbers::pi;
  for (int k = 1; k < 3600; ++k)
    if (cost(-std::numbers::pi + k * step) < cost(best)) best = -std::numbers::pi + k * step;
  while (step > 1e-10) {  // +-1 cell of the previous grid, 20 times finer
    const double centre = best;
    step /= 20.0;
    for (int k = -20; k <= 20; ++k)
      if (cost(centre + k * step) < cost(best)) best = centre + k * step;
  }
  return with_angle(best);
}

std::vector<PosePair> pairs_of(const slam::Trajectory& estimate,
                               const slam::Trajectory& reference) {
  return associate(estimate, reference, 0.0);
}

TEST(Align, RecoversAKnownTransformExactly) {
  const slam::Trajectory reference = spiral(40);
  for (const slam::Pose2 T :
       {slam::Pose2{3.0, -2.0, 2.5}, slam::Pose2{-0.5, 7.0, -3.1}, slam::Pose2{0.0, 0.0, 0.0}}) {
    // estimate = T^-1 * reference, so the transform mapping it back onto the reference is T.
    const auto pairs = pairs_of(transformed(reference, T.inverse()), reference);
    expect_pose_near(align(pairs), T, 1e-9);
  }
}

TEST(Align, WithNoiseMatchesBruteForceLeastSquares) {
  const slam::Trajectory reference = spiral(60);
  const slam::Pose2 T{1.5, -4.0, -2.2};
  slam::Trajectory estimate = transformed(reference, T.inverse());
  std::mt19937_64 rng(11);
  std::normal_distribution<double> noise(0.0, 0.05);  // metres
  for (slam::StampedPose& p : estimate) {
    p.pose.x += noise(rng);
    p.pose.y += noise(rng);
  }
  const auto pairs = pairs_of(estimate, reference);
  const slam::Pose2 closed_form = align(pairs);
  const slam::Pose2 brute = brute_force_alignment(pairs);
  expect_pose_near(closed_form, brute, 1e-6);
  EXPECT_LE(alignment_cost(pairs, closed_form), alignment_cost(pairs, brute) + 1e-12);
  // Optimality: any small move of (x, y, theta) does not lower the cost.
  for (const slam::Pose2 d :
       {slam::Pose2{1e-4, 0, 0}, slam::Pose2{0, 1e-4, 0}, slam::Pose2{0, 0, 1e-4},
        slam::Pose2{-1e-4, 0, 0}, slam::Pose2{0, -1e-4, 0}, slam::Pose2{0, 0, -1e-4}}) {
    const slam::Pose2 moved{closed_form.x + d.x, closed_form.y + d.y, closed_form.theta + d.theta};
    EXPECT_GT(alignment_cost(pairs, moved), alignment_cost(pairs, closed_form));
  }
  expect_pose_near(closed_form, T, 0.05);  // and close to the truth at this noise level
}

TEST(AlignmentCost, HandComputed) {
  // Estimate (1, 0) and (0, 1) turned by 90 deg and moved by (1, 0): (1, 1) and (0, 0); the
  // reference (1, 1) and (0, 0.5) leaves residuals 0 and 0.5: cost 0.25.
  const slam::Trajectory estimate = testing::make_trajectory({{1, 1, 0, 0}, {2, 0, 1, 0}});
  const slam::Trajectory reference = testing::make_trajectory({{1, 1, 1, 0}, {2, 0, 0.5, 0}});
  EXPECT_NEAR(alignment_cost(pairs_of(estimate, reference), {1.0, 0.0, std::numbers::pi / 2}), 0.25,
              1e-12);
}

TEST(Align, SinglePoseIsAPureTranslationAndEmptyIsRejected) {
  const slam::Trajectory reference = testing::make_trajectory({{1.0, 2.0, 3.0, 0.5}});
  const slam::Trajectory estimate = testing::make_trajectory({{1.0, -1.0, 1.0, 0.2}});
  const auto pairs = pairs_of(estimate, reference);
  expect_pose_near(align(pairs), slam::Pose2{3.0, 2.0, 0.0}, 1e-12);
  EXPECT_THROW(align(std::vector<PosePair>{}), std::invalid_argument);
}

TEST(Transformed, MovesEveryPoseAndKeepsStamps) {
  const slam::Trajectory t = testing::make_trajectory({{5.0, 1, 0, 0}, {6.0, 0, 2, 1.0}});
  const slam::Trajectory moved = transformed(t, {1.0, -1.0, std::numbers::pi / 2});
  ASSERT_EQ(moved.size(), 2U);
  EXPECT_DOUBLE_EQ(moved[1].stamp, 6.0);
  // (1, 0, 0) rotated by 90 deg -> (0, 1), plus (1, -1): (1, 0), heading 90 deg.
  expect_pose_near(moved[0].pose, {1.0, 0.0, std::numbers::pi / 2}, 1e-12);
  // (0, 2, 1) -> (-2, 0) + (1, -1) = (-1, -1), heading 1 + 90 deg.
  expect_pose_near(moved[1].pose, {-1.0, -1.0, 1.0 + std::numbers::pi / 2}, 1e-12);
}

TEST(Ate, RigidlyMovedCopyHasZeroErrorAfterAlignment) {
  const slam::Trajectory reference = spiral(50);
  const auto pairs = pairs_of(transformed(reference, slam::Pose2{10.0, -3.0, 1.2}), reference);
  const AteResult result = ate(pairs, align(pairs));
  EXPECT_EQ(result.translation_m.count, 50U);
  EXPECT_LT(result.translation_m.max, 1e-9);
  EXPECT_LT(result.rotation_deg.max, 1e-7);
  expect_pose_near(result.alignment, slam::Pose2{10.0, -3.0, 1.2}.inverse(), 1e-9);
}

TEST(Ate, WithoutAlignmentATranslationOffsetIsTheError) {
  const slam::Trajectory reference = spiral(30);
  slam::Trajectory estimate = reference;
  for (slam::StampedPose& p : estimate) {
    p.pose.x += 0.3;
    p.pose.y += 0.4;
  }
  const AteResult result = ate(pairs_of(estimate, reference));
  for (double v : {result.translation_m.rmse, result.translation_m.mean,
                   result.translation_m.median, result.translation_m.min, result.translation_m.max})
    EXPECT_NEAR(v, 0.5, 1e-12);
  EXPECT_NEAR(result.translation_m.std, 0.0, 1e-12);
  EXPECT_NEAR(result.rotation_deg.max, 0.0, 1e-12);
}

TEST(Ate, WithoutAlignmentHandComputedRotationAboutTheOrigin) {
  // Reference at (1, 0) and (2, 0) heading 0; estimate rotated by 90 deg about the origin:
  // (0, 1) and (0, 2) heading 90 deg. Errors sqrt(2) and 2 sqrt(2), RMSE sqrt((2 + 8) / 2).
  const slam::Trajectory reference = testing::make_trajectory({{0, 1, 0, 0}, {1, 2, 0, 0}});
  const auto pairs = pairs_of(transformed(reference, {0, 0, std::numbers::pi / 2}), reference);
  const AteResult result = ate(pairs);
  EXPECT_NEAR(result.translation_m.rmse, std::sqrt(5.0), 1e-12);
  EXPECT_NEAR(result.translation_m.mean, 1.5 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(result.translation_m.std, 0.5 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(result.rotation_deg.mean, 90.0, 1e-9);
  // Aligned, the same pairs have no error.
  EXPECT_LT(ate(pairs, align(pairs)).translation_m.max, 1e-12);
}

TEST(Ate, HeadingOffsetIsARotationalError) {
  const slam::Trajectory reference = spiral(10);
  slam::Trajectory estimate = reference;
  for (slam::StampedPose& p : estimate) p.pose.theta = slam::wrap_angle(p.pose.theta + 0.1);
  const AteResult result = ate(pairs_of(estimate, reference));
  EXPECT_NEAR(result.translation_m.max, 0.0, 1e-12);
  EXPECT_NEAR(result.rotation_deg.min, 0.1 * 180.0 / std::numbers::pi, 1e-9);
  EXPECT_NEAR(result.rotation_deg.max, 0.1 * 180.0 / std::numbers::pi, 1e-9);
  EXPECT_THROW(ate(std::vector<PosePair>{}), std::invalid_argument);
}

}  // namespace
}  // namespace antslam::eval
