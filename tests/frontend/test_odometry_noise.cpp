#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "antslam/frontend/odometry_benchmark.hpp"
#include "antslam/frontend/odometry_noise.hpp"
#include "antslam/frontend/simulator.hpp"

namespace antslam::frontend {
namespace {

OdometryNoise silent() { return {0.0, 0.0, 0.0, 0.0}; }

TEST(OdometryNoise, ZeroNoiseReproducesThePath) {
  SimulationSettings sim;
  sim.beams = 2;
  const std::vector<Eigen::Vector2d> waypoints = loop_waypoints();
  const SimulatedRun run = simulate_run(loop_world(), waypoints, sim, 3);
  std::vector<slam::Pose2> path;
  for (const auto& p : run.truth) path.push_back(p.pose);
  aco::Rng rng(1);
  const std::vector<slam::Pose2> odometry = noisy_odometry(path, silent(), rng);
  ASSERT_EQ(odometry.size(), path.size());
  for (std::size_t i = 0; i < path.size(); ++i) {
    EXPECT_NEAR(odometry[i].x, path[i].x, 1e-12) << i;
    EXPECT_NEAR(odometry[i].y, path[i].y, 1e-12) << i;
    EXPECT_NEAR(slam::wrap_angle(odometry[i].theta - path[i].theta), 0.0, 1e-12) << i;
  }
}

TEST(OdometryNoise, HeadingBiasBendsAStraightPathByHand) {
  const std::vector<slam::Pose2> path{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  OdometryNoise noise = silent();
  noise.heading_bias = 0.1;
  aco::Rng rng(1);
  const std::vector<slam::Pose2> o = noisy_odometry(path, noise, rng);
  // o_1 = (1, 0, 0.1); o_2 = o_1 (+) (1, 0, 0.1) = (1 + cos 0.1, sin 0.1, 0.2).
  EXPECT_NEAR(o[1].x, 1.0, 1e-15);
  EXPECT_NEAR(o[1].theta, 0.1, 1e-15);
  EXPECT_NEAR(o[2].x, 1.0 + std::cos(0.1), 1e-15);
  EXPECT_NEAR(o[2].y, std::sin(0.1), 1e-15);
  EXPECT_NEAR(o[2].theta, 0.2, 1e-15);
}

TEST(OdometryNoise, StepErrorsHaveTheModelledSpread) {
  // Steps of 0.5 m and a quarter turn: per step, x error std = 0.1 * 0.5, y error std half of
  // it, heading error std = 0.2 * pi/2 + 0.04 * 0.5 around the bias 0.03 * 0.5.
  const OdometryNoise noise{0.1, 0.2, 0.04, 0.03};
  const slam::Pose2 step{0.5, 0.0, 1.5707963267948966};
  std::vector<slam::Pose2> path{{}};
  for (int i = 0; i < 20000; ++i) path.push_back(path.back() * step);
  aco::Rng rng(9);
  const std::vector<slam::Pose2> o = noisy_odometry(path, noise, rng);
  double sx = 0, sxx = 0, syy = 0, st = 0, stt = 0;
  for (std::size_t i = 1; i < o.size(); ++i) {
    const slam::Pose2 u = slam::between(o[i - 1], o[i]);
    const double ex = u.x - step.x, ey = u.y - step.y;
    const double et = slam::wrap_angle(u.theta - step.theta);
    sx += ex;
    sxx += ex * ex;
    syy += ey * ey;
    st += et;
    stt += et * et;
  }
  const double n = static_cast<double>(o.size() - 1);
  EXPECT_NEAR(sx / n, 0.0, 0.002);
  EXPECT_NEAR(std::sqrt(sxx / n), 0.05, 0.002);
  EXPECT_NEAR(std::sqrt(syy / n), 0.025, 0.001);
  const double mean_t = st / n;
  EXPECT_NEAR(mean_t, 0.015, 0.01);
  EXPECT_NEAR(std::sqrt(stt / n - mean_t * mean_t), 0.2 * 1.5707963267948966 + 0.02, 0.01);
}

TEST(OdometryNoise, SameSeedSameOdometry) {
  const std::vector<slam::Pose2> path{{0, 0, 0}, {1, 0, 0.2}, {2, 1, 0.4}};
  aco::Rng a(4), b(4), c(5);
  const auto x = noisy_odometry(path, {}, a), y = noisy_odometry(path, {}, b),
             z = noisy_odometry(path, {}, c);
  EXPECT_EQ(x[2].x, y[2].x);
  EXPECT_EQ(x[2].theta, y[2].theta);
  EXPECT_NE(x[2].x, z[2].x);
}

TEST(OdometryNoise, RejectsNegativeOrNonFiniteNoise) {
  OdometryNoise noise;
  noise.drift = -0.1;
  try {
    validate(noise);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "odometry noise: drift must be a finite number >= 0");
  }
  noise = {};
  noise.heading_bias = NAN;
  EXPECT_THROW(validate(noise), std::invalid_argument);
}

LaserLog corrected_log(std::vector<double> stamps) {
  LaserLog log;
  log.source = "corrected.log";
  for (std::size_t i = 0; i < stamps.size(); ++i) {
    LaserScan scan;
    scan.stamp = stamps[i];
    scan.odometry = slam::Pose2{static_cast<double>(i), 0.5 * static_cast<double>(i), 0.1};
    log.scans.push_back(scan);
  }
  log.odometry = {{0.0, {}}, {1.0, {}}};
  return log;
}

TEST(OdometryBenchmark, RestampsOnlyStampsThatDoNotIncrease) {
  LaserLog increasing = corrected_log({1.0, 1.5, 3.0});
  EXPECT_FALSE(restamp_evenly(increasing));
  EXPECT_EQ(increasing.scans[1].stamp, 1.5);
  LaserLog repeated = corrected_log({10.0, 10.0, 10.0, 13.0});
  EXPECT_TRUE(restamp_evenly(repeated));
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_DOUBLE_EQ(repeated.scans[i].stamp, 10.0 + static_cast<double>(i));
  LaserLog constant = corrected_log({5.0, 5.0});
  EXPECT_TRUE(restamp_evenly(constant));
  EXPECT_DOUBLE_EQ(constant.scans[1].stamp, 6.0);  // an empty span: 1 s apart
}

TEST(OdometryBenchmark, ZeroNoiseOdometryIsTheReferenceAndOdomMessagesAreDropped) {
  const OdometryBenchmark b = simulate_odometry(corrected_log({0.0, 0.0, 1.0}), silent(), 9);
  EXPECT_TRUE(b.restamped);
  EXPECT_EQ(b.dropped_odometry, 2U);
  EXPECT_TRUE(b.log.odometry.empty());
  ASSERT_EQ(b.reference.size(), 3U);
  ASSERT_EQ(b.odometry.size(), 3U);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(b.reference[i].stamp, b.log.scans[i].stamp);
    EXPECT_EQ(b.reference[i].pose.x, static_cast<double>(i));
    EXPECT_NEAR(b.odometry[i].pose.x, b.reference[i].pose.x, 1e-12);
    EXPECT_NEAR(b.odometry[i].pose.y, b.reference[i].pose.y, 1e-12);
    EXPECT_EQ(b.log.scans[i].odometry.x, b.odometry[i].pose.x);
  }
}

TEST(OdometryBenchmark, NoiseIsSeededAndLeavesTheReferenceAlone) {
  const OdometryNoise noise;
  const OdometryBenchmark a = simulate_odometry(corrected_log({0, 1, 2, 3}), noise, 4);
  const OdometryBenchmark b = simulate_odometry(corrected_log({0, 1, 2, 3}), noise, 4);
  const OdometryBenchmark c = simulate_odometry(corrected_log({0, 1, 2, 3}), noise, 5);
  EXPECT_EQ(a.odometry.back().pose.x, b.odometry.back().pose.x);
  EXPECT_NE(a.odometry.back().pose.x, c.odometry.back().pose.x);
  EXPECT_EQ(a.reference.back().pose.x, 3.0);
  OdometryNoise bad;
  bad.linear = -1.0;
  EXPECT_THROW(simulate_odometry(corrected_log({0, 1}), bad, 1), std::invalid_argument);
}

}  // namespace
}  // namespace antslam::frontend
