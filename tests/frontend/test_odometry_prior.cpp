// The odometry as the scan matcher's prior: step covariance, Gaussian fusion, flat directions,
// and the matcher's decisions (fuse, overrule a failed odometry, fall back to it).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "antslam/frontend/odometry_prior.hpp"
#include "antslam/frontend/scan_matcher.hpp"
#include "antslam/frontend/simulator.hpp"

namespace antslam::frontend {
namespace {

Eigen::Matrix3d diagonal(double a, double b, double c) {
  return Eigen::Vector3d(a, b, c).asDiagonal();
}

TEST(OdometryPrior, StepCovarianceGrowsWithLengthAndTurn) {
  const OdometryPrior prior;  // 0.1 m/m, 0.1 rad/rad, 0.02 rad/m, floors 0.02 m, 0.01 rad
  const Eigen::Matrix3d c = step_covariance(prior, slam::Pose2{3.0, 4.0, -0.5});
  // d = 5 m: linear 0.1 * 5 + 0.02 = 0.52 m; heading 0.1 * 0.5 + 0.02 * 5 + 0.01 = 0.16 rad.
  EXPECT_NEAR(c(0, 0), 0.52 * 0.52, 1e-12);
  EXPECT_NEAR(c(1, 1), 0.52 * 0.52, 1e-12);
  EXPECT_NEAR(c(2, 2), 0.16 * 0.16, 1e-12);
  EXPECT_EQ(c(0, 1), 0.0);
  const Eigen::Matrix3d still = step_covariance(prior, slam::Pose2{});
  EXPECT_NEAR(still(0, 0), 0.02 * 0.02, 1e-15);
  EXPECT_NEAR(still(2, 2), 0.01 * 0.01, 1e-15);
}

TEST(OdometryPrior, RejectsNonsense) {
  OdometryPrior p;
  p.linear = -0.1;
  EXPECT_THROW(validate(p), std::invalid_argument);
  p = {};
  p.min_linear = 0.0;  // a step known exactly would make the fallback covariance singular
  EXPECT_THROW(validate(p), std::invalid_argument);
  p = {};
  p.drift = std::nan("");
  EXPECT_THROW(validate(p), std::invalid_argument);
  EXPECT_NO_THROW(validate(OdometryPrior{}));
}

TEST(OdometryPrior, FusionIsTheInformationWeightedMean) {
  const slam::Gaussian2 match(slam::Pose2{0.0, 0.0, 0.0}, diagonal(1.0, 4.0, 1.0));
  const slam::Gaussian2 prediction(slam::Pose2{1.0, 2.0, 0.2}, diagonal(1.0, 1.0, 3.0));
  const slam::Gaussian2 f = fuse(match, prediction);
  // Per axis (diagonal): mu = (mu_m / v_m + mu_p / v_p) / (1 / v_m + 1 / v_p).
  EXPECT_NEAR(f.mean().x, 0.5, 1e-12);
  EXPECT_NEAR(f.mean().y, 2.0 / 1.25, 1e-12);
  EXPECT_NEAR(f.mean().theta, (0.2 / 3.0) / (1.0 + 1.0 / 3.0), 1e-12);
  EXPECT_NEAR(f.covariance()(0, 0), 0.5, 1e-12);
  EXPECT_NEAR(f.covariance()(1, 1), 0.8, 1e-12);
  EXPECT_NEAR(f.covariance()(2, 2), 0.75, 1e-12);
}

TEST(OdometryPrior, FusionWrapsTheHeading) {
  // Headings 3.1 and -3.1 are 0.083 rad apart across pi: the fused heading lies between them,
  // at pi, not at 0.
  const slam::Gaussian2 a(slam::Pose2{0.0, 0.0, 3.1}, diagonal(1.0, 1.0, 0.01));
  const slam::Gaussian2 b(slam::Pose2{0.0, 0.0, -3.1}, diagonal(1.0, 1.0, 0.01));
  EXPECT_NEAR(std::abs(fuse(a, b).mean().theta), std::numbers::pi, 1e-9);
}

TEST(OdometryPrior, FlatDirectionIsFoundInAnyOrientation) {
  const slam::Gaussian2 prediction(slam::Pose2{}, diagonal(0.01, 0.01, 0.01));
  // Along x the match knows 0.3 m (variance 0.09 > 0.01): flatter than the odometry.
  EXPECT_TRUE(flatter_than(slam::Gaussian2(slam::Pose2{}, diagonal(0.09, 1e-4, 1e-4)), prediction));
  EXPECT_FALSE(
      flatter_than(slam::Gaussian2(slam::Pose2{}, diagonal(1e-3, 1e-4, 1e-4)), prediction));
  // The same corridor turned by 45 degrees, against an odometry that is sure along x and y.
  Eigen::Matrix3d turned = Eigen::Matrix3d::Identity() * 1e-4;
  turned.topLeftCorner<2, 2>() << 0.045, 0.04495, 0.04495, 0.045;
  EXPECT_TRUE(flatter_than(slam::Gaussian2(slam::Pose2{}, turned), prediction));
}

// The matcher's decision, on hand-made matches around one prediction.
class MatchDecision : public ::testing::Test {
 protected:
  ScanMatcherSettings settings;
  ScanMatcher matcher{settings};
  const slam::Gaussian2 prediction{slam::Pose2{1.0, 2.0, 0.3}, diagonal(0.01, 0.01, 0.0025)};

  MatchResult match_at(const slam::Pose2& pose, const Eigen::Matrix3d& covariance, double fit) {
    MatchResult m;
    m.gaussian = slam::Gaussian2(pose, covariance);
    m.status = MatchStatus::matched;
    m.inlier_fraction = fit;
    return m;
  }
};

TEST_F(MatchDecision, AMatchNearTheOdometryIsFused) {
  const slam::Pose2 near{1.05, 2.0, 0.31};
  const MatchResult r =
      matcher.check_against(match_at(near, diagonal(1e-4, 1e-4, 1e-5), 0.5), prediction);
  EXPECT_EQ(r.status, MatchStatus::matched);
  EXPECT_LT(r.prior_mahalanobis, settings.divergence_sigmas);
  // The precise match dominates: it moves by 1 % of the way towards the prediction.
  EXPECT_NEAR(r.pose().x, 1.05 - 0.05 * 1e-4 / (1e-4 + 0.01), 1e-9);
  EXPECT_FALSE(r.odometry_along_flat);
}

TEST_F(MatchDecision, AFarMatchThatFitsPoorlyFallsBackToTheInflatedOdometry) {
  const MatchResult r = matcher.check_against(
      match_at(slam::Pose2{2.0, 2.0, 1.8}, diagonal(1e-4, 1e-4, 1e-5), 0.6), prediction);
  EXPECT_EQ(r.status, MatchStatus::diverged);
  EXPECT_GT(r.prior_mahalanobis, settings.divergence_sigmas);
  EXPECT_DOUBLE_EQ(r.pose().x, 1.0);
  EXPECT_DOUBLE_EQ(r.pose().theta, 0.3);
  EXPECT_NEAR(r.gaussian.covariance()(0, 0), settings.fallback_inflation * 0.01, 1e-12);
  EXPECT_FALSE(r.matched());
}

TEST_F(MatchDecision, AFarMatchThatFitsWellOverrulesAFailedOdometry) {
  const slam::Pose2 far{2.0, 2.0, 1.8};
  const MatchResult r =
      matcher.check_against(match_at(far, diagonal(1e-4, 1e-4, 1e-5), 0.95), prediction);
  EXPECT_EQ(r.status, MatchStatus::matched);
  EXPECT_DOUBLE_EQ(r.pose().x, far.x);  // not pulled towards the failed odometry
  EXPECT_DOUBLE_EQ(r.pose().theta, far.theta);
}

TEST_F(MatchDecision, AlongAFlatDirectionTheOdometryKeepsTheEstimate) {
  // A corridor along x: the match slid 0.25 m along it, is certain across it.
  const MatchResult r = matcher.check_against(
      match_at(slam::Pose2{1.25, 2.01, 0.3}, diagonal(0.25, 1e-4, 1e-5), 0.9), prediction);
  EXPECT_TRUE(r.odometry_along_flat);
  EXPECT_NEAR(r.pose().x, 1.0, 0.015);  // the odometry's, within 4 % of the slide
  EXPECT_NEAR(r.pose().y, 2.01, 1e-4);  // the match's
}

TEST(ScanMatcherPrior, AScanOfAnotherPlaceDoesNotPullTheRobotToAWrongPeak) {
  // The local map is a room; the scan comes from the ring corridor (people, a wrong map): any
  // peak it finds is wrong. The result stays within divergence_sigmas of the odometry
  // prediction, or is the prediction itself.
  SimulationSettings sim;
  aco::Rng rng(4);
  const ScanMatcherSettings s;
  ScanMatcher matcher(s);
  const slam::Pose2 here{0.0, -1.0, 0.2};
  matcher.insert(map_points(simulate_scan(room_world(), here, sim, rng), s), here);
  for (const slam::Pose2 elsewhere :
       {slam::Pose2{5.0, 0.2, 0.0}, slam::Pose2{10.0, -0.3, 1.2}, slam::Pose2{20.0, 7.0, 1.6}}) {
    const Points points = matching_points(simulate_scan(loop_world(), elsewhere, sim, rng), s);
    const slam::Gaussian2 prediction(here, diagonal(0.01, 0.01, 0.0025));
    const MatchResult r =
        matcher.check_against(matcher.match(points, here, prediction.covariance()), prediction);
    if (r.status == MatchStatus::diverged) {
      EXPECT_DOUBLE_EQ(r.pose().x, here.x);
    } else {
      EXPECT_TRUE(r.prior_mahalanobis <= s.divergence_sigmas || r.inlier_fraction >= s.trusted_fit);
    }
  }
}

TEST(ScanMatcherPrior, TheSearchWindowGrowsWithTheOdometryStep) {
  // A scan 1.2 m from the prediction: beyond the default 0.5 m window (and the fine search
  // and refinement around its edge), inside 3 sigma of a long step's covariance (0.1 m/m over
  // 4 m: 0.42 m std).
  SimulationSettings sim;
  aco::Rng rng(5);
  ScanMatcherSettings s;
  s.recovery_fraction = 0.0;  // no recovery search: only the window can find it
  const slam::Pose2 truth{0.5, -0.8, 0.4};
  const LaserScan scan = simulate_scan(room_world(), truth, sim, rng);
  const slam::Pose2 prediction = truth * slam::Pose2{1.2, 0.0, 0.0};
  const Eigen::Matrix3d long_step = step_covariance(s.odometry, slam::Pose2{4.0, 0.0, 0.0});
  ScanMatcher wide(s), narrow(s);
  wide.insert(map_points(scan, s), truth);
  narrow.insert(map_points(scan, s), truth);
  const MatchResult found = wide.match(matching_points(scan, s), prediction, long_step);
  EXPECT_NEAR(found.pose().x, truth.x, 0.01);
  EXPECT_NEAR(found.pose().y, truth.y, 0.01);
  const MatchResult missed = narrow.match(matching_points(scan, s), prediction);
  EXPECT_GT(std::hypot(missed.pose().x - truth.x, missed.pose().y - truth.y), 0.1);
}

}  // namespace
}  // namespace antslam::frontend
