// The scan matcher on simulated scans: known offsets, a featureless corridor, honest covariance.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "antslam/frontend/nees.hpp"
#include "antslam/frontend/scan_matcher.hpp"
#include "antslam/frontend/simulator.hpp"

namespace antslam::frontend {
namespace {

using V = Eigen::Vector2d;

TEST(ScanMatcher, RecoversAScanShiftedAndRotatedAgainstItself) {
  SimulationSettings sim;
  sim.range_noise = 0.0;
  aco::Rng rng(1);
  const slam::Pose2 truth{0.5, -0.8, 0.4};
  const LaserScan scan = simulate_scan(room_world(), truth, sim, rng);
  const ScanMatcherSettings s;
  ScanMatcher matcher(s);
  matcher.insert(map_points(scan, s), truth);
  // The same scan, predicted 0.3 m and 0.2 rad away: it must come back onto itself.
  const slam::Pose2 offset{0.3, -0.25, 0.2};
  const MatchResult r = matcher.match(matching_points(scan, s), truth * offset);
  EXPECT_TRUE(r.matched());
  EXPECT_NEAR(r.pose().x, truth.x, 0.005);
  EXPECT_NEAR(r.pose().y, truth.y, 0.005);
  EXPECT_NEAR(r.pose().theta, truth.theta, 0.002);
  EXPECT_GT(r.inlier_fraction, 0.95);
}

TEST(ScanMatcher, RecoversTheMotionBetweenTwoScansOfARoom) {
  SimulationSettings sim;
  aco::Rng rng(2);
  const slam::Pose2 first{-1.0, -1.0, 0.3};
  const slam::Pose2 second = first * slam::Pose2{0.45, 0.1, 0.25};
  const ScanMatcherSettings s;
  ScanMatcher matcher(s);
  matcher.insert(map_points(simulate_scan(room_world(), first, sim, rng), s), first);
  const LaserScan scan = simulate_scan(room_world(), second, sim, rng);
  const MatchResult r = matcher.match(matching_points(scan, s), first);  // odometry said "still"
  EXPECT_NEAR(r.pose().x, second.x, 0.02);
  EXPECT_NEAR(r.pose().y, second.y, 0.02);
  EXPECT_NEAR(r.pose().theta, second.theta, 0.01);
  // The truth lies inside the Gaussian's 3-sigma region.
  EXPECT_LT(r.gaussian.mahalanobis_squared(second), 14.2);  // chi^2_3 at 99.7 %
}

TEST(ScanMatcher, CovarianceGrowsAlongAFeaturelessCorridor) {
  SimulationSettings sim;
  aco::Rng rng(3);
  const World corridor = corridor_world();
  const ScanMatcherSettings s;
  ScanMatcher matcher(s);
  // The map: scans along the corridor, so that its walls are mapped well beyond the scan.
  for (int k = -12; k <= 12; ++k) {
    const slam::Pose2 p{0.5 * k, 0.02 * (k % 3), 0.0};
    matcher.insert(map_points(simulate_scan(corridor, p, sim, rng), s), p);
  }
  const slam::Pose2 truth{0.1, 0.2, 0.05};
  const LaserScan scan = simulate_scan(corridor, truth, sim, rng);
  const MatchResult r = matcher.match(matching_points(scan, s), slam::Pose2{0.0, 0.25, 0.0});
  const Eigen::Matrix3d& c = r.gaussian.covariance();
  // Across the corridor and in heading the walls pin the pose down; along it nothing does.
  EXPECT_NEAR(r.pose().y, truth.y, 0.01);
  EXPECT_NEAR(r.pose().theta, truth.theta, 0.005);
  EXPECT_GT(c(0, 0), 100.0 * c(1, 1));
  EXPECT_GT(std::sqrt(c(0, 0)), 0.1);
  // In a room the same scan matcher is certain in every direction.
  ScanMatcher room(s);
  const slam::Pose2 here{0.0, -1.0, 0.2};
  room.insert(map_points(simulate_scan(room_world(), here, sim, rng), s), here);
  const MatchResult q =
      room.match(matching_points(simulate_scan(room_world(), here, sim, rng), s), here);
  EXPECT_LT(std::sqrt(q.gaussian.covariance()(0, 0)), 0.02);
  EXPECT_LT(std::sqrt(q.gaussian.covariance()(1, 1)), 0.02);
}

TEST(ScanMatcher, CalibratedTemperatureGivesHonestCovariances) {
  // NEES averages about 3 (the dimension) on simulated scans with the default temperature.
  SimulationSettings sim;
  sim.step = 0.3;
  const ScanMatcherSettings s;
  const std::vector<V> path{V(-3, -2.3), V(3.3, -2.3), V(3.3, 2.3), V(0.5, 2.3), V(0.5, -0.5)};
  const NeesStats room = simulated_nees(simulate_run(room_world(), path, sim, 7), s);
  const std::vector<V> loop{V(0, 0), V(20, 0), V(20, 14)};
  const NeesStats ring = simulated_nees(simulate_run(loop_world(), loop, sim, 7), s);
  const double mean =
      (room.mean * static_cast<double>(room.count) + ring.mean * static_cast<double>(ring.count)) /
      static_cast<double>(room.count + ring.count);
  EXPECT_GT(mean, 1.0);
  EXPECT_LT(mean, 5.0);
  // A much colder likelihood is overconfident, a much hotter one underconfident.
  ScanMatcherSettings cold = s;
  cold.temperature = s.temperature / 10.0;
  EXPECT_GT(simulated_nees(simulate_run(room_world(), path, sim, 7), cold).mean, 3.0 * room.mean);
}

TEST(ScanMatcher, FollowsASimulatedRunWithNoisyOdometry) {
  SimulationSettings sim;
  sim.odometry_noise_linear = 0.1;
  sim.odometry_noise_angular = 0.1;
  const std::vector<V> path{V(-3, -2.3), V(3.3, -2.3), V(3.3, 2.3), V(0.5, 2.3)};
  const SimulatedRun run = simulate_run(room_world(), path, sim, 9);
  ScanMatcher matcher{ScanMatcherSettings{}};
  double worst = 0.0, odometry_worst = 0.0;
  const slam::Pose2 start = run.truth[0].pose;
  for (std::size_t k = 0; k < run.truth.size(); ++k) {
    const MatchResult r = matcher.add_scan(run.log.scans[k]);
    // The matcher's frame starts at the first pose.
    const slam::Pose2 truth = slam::between(start, run.truth[k].pose);
    worst = std::max(worst, std::hypot(r.pose().x - truth.x, r.pose().y - truth.y));
    const slam::Pose2 odo = slam::between(run.log.scans[0].odometry, run.log.scans[k].odometry);
    odometry_worst = std::max(odometry_worst, std::hypot(odo.x - truth.x, odo.y - truth.y));
  }
  EXPECT_LT(worst, 0.05);
  EXPECT_GT(odometry_worst, 5.0 * worst);
}

TEST(ScanMatcher, RejectsNonsenseSettings) {
  ScanMatcherSettings s;
  s.resolution = 0.0;
  EXPECT_THROW(ScanMatcher{s}, std::invalid_argument);
  s = {};
  s.coarse_resolution = 0.01;  // finer than the fine grid
  EXPECT_THROW(ScanMatcher{s}, std::invalid_argument);
  s = {};
  s.temperature = -1.0;
  EXPECT_THROW(ScanMatcher{s}, std::invalid_argument);
}

}  // namespace
}  // namespace antslam::frontend
