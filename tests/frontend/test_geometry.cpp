// Scan points, moment matching (eqs. 5-6), covariance propagation and the uncertainty graph.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "antslam/aco/random.hpp"
#include "antslam/frontend/pose_covariance.hpp"
#include "antslam/frontend/scan_points.hpp"
#include "antslam/frontend/uncertainty_graph.hpp"
#include "antslam/slamgraph/gaussian2.hpp"

namespace antslam::frontend {
namespace {

constexpr double kPi = std::numbers::pi;

LaserScan make_scan(std::vector<float> ranges, double step) {
  LaserScan s;
  s.ranges = std::move(ranges);
  s.first_angle = 0.0;
  s.angle_step = step;
  s.max_range = 10.0;
  return s;
}

TEST(ScanPoints, DropsInvalidReadingsAndAppliesTheLaserPose) {
  LaserScan s = make_scan({2.0F, 0.05F, 10.0F, 3.0F, 12.0F}, kPi / 4);
  s.laser_pose = slam::Pose2{0.5, 0.0, 0.0};
  const ScanSurfaces surfaces = scan_surfaces(s, 0.1, 30.0, 0.17);
  ASSERT_EQ(surfaces.points.size(), 2U);  // too short, max-range and beyond-max dropped
  EXPECT_NEAR(surfaces.points[0].x(), 2.5, 1e-12);
  EXPECT_NEAR(surfaces.points[1].x(), 0.5 + 3.0 * std::cos(3 * kPi / 4), 1e-12);
  EXPECT_NEAR(surfaces.points[1].y(), 3.0 * std::sin(3 * kPi / 4), 1e-12);
  EXPECT_EQ(surfaces.joins_next[0], 0);  // not neighbours: beams in between were dropped
}

TEST(ScanPoints, JoinsOneSurfaceAndSplitsAtDepthJumps) {
  // A wall at x = 2 seen by beams 0.01 rad apart, then a jump to a wall 4 m away.
  std::vector<float> ranges;
  for (int k = 0; k < 5; ++k) ranges.push_back(static_cast<float>(2.0 / std::cos(0.01 * k)));
  for (int k = 5; k < 8; ++k) ranges.push_back(static_cast<float>(4.0 / std::cos(0.01 * k)));
  const ScanSurfaces s = scan_surfaces(make_scan(ranges, 0.01), 0.1, 30.0, 10.0 * kPi / 180.0);
  const std::vector<std::uint8_t> joins{1, 1, 1, 1, 0, 1, 1, 0};
  EXPECT_EQ(s.joins_next, joins);
  // Isolated returns are not matched; dense points fill the joined segments.
  const ScanSurfaces lone = scan_surfaces(make_scan({2.0F, 5.0F, 2.0F}, 0.01), 0.1, 30.0, 0.17);
  EXPECT_TRUE(supported_points(lone).empty());
  EXPECT_EQ(supported_points(s).size(), 8U);
  const Points dense = dense_points(s, 0.005);
  EXPECT_GT(dense.size(), 8U);
  for (std::size_t k = 1; k < dense.size(); ++k) {
    const double gap = (dense[k] - dense[k - 1]).norm();
    if (gap < 1.0) {
      EXPECT_LE(gap, 0.005 + 1e-9);
    }
  }
}

TEST(ScanPoints, ThinningKeepsOnePointPerCell) {
  const Points p{{0.01, 0.01}, {0.02, 0.03}, {0.11, 0.0}, {-0.01, 0.0}};
  const Points kept = thin_points(p, 0.1);
  ASSERT_EQ(kept.size(), 3U);
  EXPECT_EQ(kept[0], p[0]);
  EXPECT_EQ(kept[1], p[2]);
  EXPECT_EQ(kept[2], p[3]);
}

TEST(MomentMatching, ReproducesEquationsFiveAndSixByHand) {
  // Two candidates with weights 1 and 3 (log weights differ by log 3).
  const std::vector<WeightedPose> c{{slam::Pose2{0.0, 0.0, 0.1}, 0.0},
                                    {slam::Pose2{1.0, 2.0, 0.3}, std::log(3.0)}};
  const slam::Gaussian2 g =
      moment_match(c, Eigen::Matrix3d::Zero() + 1e-12 * Eigen::Matrix3d::Identity());
  EXPECT_NEAR(g.mean().x, 0.75, 1e-12);
  EXPECT_NEAR(g.mean().y, 1.5, 1e-12);
  EXPECT_NEAR(g.mean().theta,
              std::atan2(0.25 * std::sin(0.1) + 0.75 * std::sin(0.3),
                         0.25 * std::cos(0.1) + 0.75 * std::cos(0.3)),
              1e-12);
  // Var of a two-point distribution: p (1 - p) d^2 with p = 1/4.
  EXPECT_NEAR(g.covariance()(0, 0), 0.1875 * 1.0 + 1e-12, 1e-12);
  EXPECT_NEAR(g.covariance()(1, 1), 0.1875 * 4.0 + 1e-12, 1e-12);
  EXPECT_NEAR(g.covariance()(0, 1), 0.1875 * 2.0, 1e-12);
}

TEST(MomentMatching, HeadingsAverageAcrossPi) {
  const std::vector<WeightedPose> c{{slam::Pose2{0, 0, kPi - 0.1}, 0.0},
                                    {slam::Pose2{0, 0, -kPi + 0.1}, 0.0}};
  const slam::Gaussian2 g = moment_match(c, 1e-9 * Eigen::Matrix3d::Identity());
  EXPECT_NEAR(std::abs(g.mean().theta), kPi, 1e-9);
  EXPECT_NEAR(g.covariance()(2, 2), 0.01 + 1e-9, 1e-9);
}

TEST(CovariancePropagation, MatchesMonteCarlo) {
  const slam::Pose2 a{1.0, -2.0, 0.7}, b{3.0, 1.0, -0.4};
  Eigen::Matrix3d ca, cb;
  ca << 0.04, 0.01, 0.002, 0.01, 0.02, -0.001, 0.002, -0.001, 0.003;
  cb << 0.01, 0.0, 0.0, 0.0, 0.03, 0.001, 0.0, 0.001, 0.002;
  const Eigen::Matrix3d predicted = compose_covariance(a, ca, b, cb);
  const slam::Gaussian2 ga(a, ca), gb(b, cb);
  aco::Rng rng(3);
  const int n = 40000;
  std::vector<Eigen::Vector3d> samples;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int k = 0; k < n; ++k) {
    const slam::Pose2 c = ga.sample(rng) * gb.sample(rng);
    samples.push_back(c.vector());
    mean += c.vector() / n;
  }
  Eigen::Matrix3d sampled = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& s : samples) sampled += (s - mean) * (s - mean).transpose() / n;
  // First order is close for these small angles (a few percent).
  EXPECT_LT((sampled - predicted).norm(), 0.06 * predicted.norm());
  // The inverse: (a^-1)^-1 = a, so inverting twice returns the covariance.
  EXPECT_LT((inverse_covariance(a.inverse(), inverse_covariance(a, ca)) - ca).norm(), 1e-12);
}

TEST(UncertaintyGraph, ComposesAlongTheChainAndPrefersAClosure) {
  // A chain 0 -> 1 -> 2 -> 3 and a closure 0 -> 3 that is much more certain.
  const Eigen::Matrix3d step = Eigen::Vector3d(0.01, 0.01, 0.001).asDiagonal();
  const slam::Pose2 e{2.0, 0.0, kPi / 2};
  std::vector<GraphEdge> edges{{0, 1, e, step}, {1, 2, e, step}, {2, 3, e, step}};
  std::vector<RelativeEstimate> r = relative_to(3, 4, edges);
  const slam::Pose2 chain = e * e * e;
  EXPECT_NEAR(r[0].pose.x, chain.x, 1e-12);
  EXPECT_NEAR(r[0].pose.y, chain.y, 1e-12);
  const Eigen::Matrix3d direct =
      compose_covariance(e, step, e * e, compose_covariance(e, step, e, step));
  EXPECT_LT((r[0].covariance - direct).norm(), 1e-12);
  // With the closure, node 0 is reached directly, at the closure's own (different) pose.
  const slam::Pose2 closure{0.1, -2.1, -kPi / 2};
  edges.push_back({0, 3, closure, 1e-4 * Eigen::Matrix3d::Identity()});
  r = relative_to(3, 4, edges);
  EXPECT_NEAR(r[0].pose.x, closure.x, 1e-12);
  EXPECT_NEAR(r[0].pose.y, closure.y, 1e-12);
  EXPECT_LT(r[0].covariance.trace(), direct.trace() / 10.0);
  EXPECT_TRUE(r[1].reachable);
}

}  // namespace
}  // namespace antslam::frontend
