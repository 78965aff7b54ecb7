// Distance fields, likelihood pyramids and the two exhaustive searches on them, cross-checked
// against brute force.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "antslam/aco/random.hpp"
#include "antslam/frontend/branch_and_bound.hpp"
#include "antslam/frontend/correlative_search.hpp"
#include "antslam/frontend/distance_field.hpp"
#include "antslam/frontend/likelihood_pyramid.hpp"

namespace antslam::frontend {
namespace {

using V = Eigen::Vector2d;

TEST(DistanceField, HoldsTheTruncatedDistanceToTheNearestPoint) {
  DistanceField f(0.1, 0.35);
  const std::vector<V> points{V(0.03, 0.02), V(1.0, 1.0)};
  f.insert(points);
  for (std::int64_t x = -6; x <= 14; ++x)
    for (std::int64_t y = -6; y <= 14; ++y) {
      const V c(0.1 * static_cast<double>(x), 0.1 * static_cast<double>(y));
      const double d = std::min((c - points[0]).norm(), (c - points[1]).norm());
      EXPECT_NEAR(f.at(x, y), std::min(d, 0.35), 1e-6) << x << " " << y;
    }
  EXPECT_FLOAT_EQ(f.at(1000, 1000), 0.35F);  // outside: max distance
}

TEST(DistanceField, GrowingKeepsValuesAndCells) {
  DistanceField f(0.05, 0.15);
  f.insert(std::vector<V>{V(0.0, 0.0)});
  const float before = f.at(1, 1);
  f.insert(std::vector<V>{V(40.0, -25.0)});  // far away: the grid grows
  EXPECT_FLOAT_EQ(f.at(1, 1), before);
  EXPECT_NEAR(f.at(f.cell_x(40.0), f.cell_y(-25.0)), 0.0, 1e-6);
  EXPECT_TRUE(f.bounds().contains(CellBox{0, -500, 800, 0}));
}

TEST(DistanceField, InterpolationIsBilinearWithTheRightGradient) {
  DistanceField f(0.1, 0.5);
  f.insert(std::vector<V>{V(0.0, 0.0), V(0.55, 0.2)});
  const V p(0.234, 0.117);
  V g;
  const double d = f.interpolate(p, &g);
  // Bilinear between the four cell centres.
  const double tx = 0.34, ty = 0.17;
  const double expected = (1 - tx) * (1 - ty) * f.at(2, 1) + tx * (1 - ty) * f.at(3, 1) +
                          (1 - tx) * ty * f.at(2, 2) + tx * ty * f.at(3, 2);
  EXPECT_NEAR(d, expected, 1e-9);
  const double h = 1e-6;
  EXPECT_NEAR(g.x(), (f.interpolate(p + V(h, 0)) - f.interpolate(p - V(h, 0))) / (2 * h), 1e-5);
  EXPECT_NEAR(g.y(), (f.interpolate(p + V(0, h)) - f.interpolate(p - V(0, h))) / (2 * h), 1e-5);
}

std::vector<V> random_points(aco::Rng& rng, int n, double extent) {
  std::vector<V> out;
  for (int k = 0; k < n; ++k)
    out.emplace_back(extent * (2 * rng.uniform() - 1), extent * (2 * rng.uniform() - 1));
  return out;
}

TEST(LikelihoodPyramid, EachLevelIsTheWindowMaximumOfLevelZero) {
  aco::Rng rng(5);
  DistanceField f(0.1, 0.3);
  f.insert(random_points(rng, 30, 1.5));
  const LikelihoodPyramid p(f, 0.1, 4);
  for (std::int64_t x = -22; x <= 18; x += 3)
    for (std::int64_t y = -20; y <= 19; y += 2) {
      EXPECT_NEAR(p.at(0, x, y),
                  std::exp(-f.at(x, y) * f.at(x, y) / 0.02) *
                      (f.bounds().contains(CellBox{x, y, x, y}) ? 1.0 : 0.0),
                  1e-6);
      for (int h = 1; h < 4; ++h) {
        float best = 0.0F;
        for (std::int64_t i = 0; i < (1 << h); ++i)
          for (std::int64_t j = 0; j < (1 << h); ++j) best = std::max(best, p.at(0, x + i, y + j));
        EXPECT_FLOAT_EQ(p.at(h, x, y), best) << h << " " << x << " " << y;
      }
    }
}

/// A scan-like point set: an L-shaped wall and a box, in the robot frame.
std::vector<V> shape() {
  std::vector<V> out;
  for (int k = 0; k <= 30; ++k) out.emplace_back(2.0, -1.5 + 0.1 * k);
  for (int k = 0; k <= 20; ++k) out.emplace_back(2.0 - 0.1 * k, 1.5);
  for (int k = 0; k <= 4; ++k) out.emplace_back(0.8 + 0.1 * k, -0.6);
  return out;
}

std::vector<V> placed(const slam::Pose2& pose, const std::vector<V>& points) {
  std::vector<V> out;
  for (const V& p : points) out.push_back(pose * p);
  return out;
}

TEST(CorrelativeSearch, FindsTheSameBestPoseAsBruteForce) {
  DistanceField f(0.05, 0.15);
  const slam::Pose2 truth{0.12, -0.07, 0.05};
  f.insert(placed(truth, shape()));
  const slam::Pose2 center{0.0, 0.0, 0.0};
  const SearchWindow w{0.2, 0.1, 0.025};
  const SearchResult found = correlative_search(f, shape(), center, w);
  double best = std::numeric_limits<double>::infinity();
  slam::Pose2 arg;
  for (int k = -4; k <= 4; ++k)
    for (int dy = -4; dy <= 4; ++dy)
      for (int dx = -4; dx <= 4; ++dx) {
        const slam::Pose2 p{0.05 * dx, 0.05 * dy, 0.025 * k};
        double sum = 0.0;
        for (const V& q : placed(p, shape())) {
          const double d = f.at(f.cell_x(q.x()), f.cell_y(q.y()));
          sum += d * d;
        }
        if (sum < best) {
          best = sum;
          arg = p;
        }
      }
  EXPECT_NEAR(found.squared_distance, best, 1e-9);
  EXPECT_NEAR(found.pose.x, arg.x, 1e-12);
  EXPECT_NEAR(found.pose.y, arg.y, 1e-12);
  EXPECT_NEAR(found.pose.theta, arg.theta, 1e-12);
  // The truth lies between lattice poses; the best is within one lattice step of it.
  EXPECT_NEAR(found.pose.x, truth.x, 0.051);
  EXPECT_NEAR(found.pose.y, truth.y, 0.051);
  EXPECT_NEAR(found.pose.theta, truth.theta, 0.026);
}

TEST(CorrelativeSearch, PeaksAreSeparateAndBestFirst) {
  DistanceField f(0.05, 0.15);
  f.insert(placed(slam::Pose2{}, shape()));
  const std::vector<SearchResult> peaks =
      correlative_peaks(f, shape(), slam::Pose2{0.02, 0.0, 0.0}, {0.4, 0.2, 0.05}, {}, 3);
  ASSERT_EQ(peaks.size(), 3U);
  EXPECT_LE(peaks[0].score, peaks[1].score);
  EXPECT_LE(peaks[1].score, peaks[2].score);
  EXPECT_NEAR(peaks[0].pose.x, 0.02, 1e-9);  // the lattice point nearest the truth (0)
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = i + 1; j < 3; ++j) {
      const bool near = std::abs(peaks[i].pose.x - peaks[j].pose.x) <= 0.1 + 1e-9 &&
                        std::abs(peaks[i].pose.y - peaks[j].pose.y) <= 0.1 + 1e-9 &&
                        std::abs(peaks[i].pose.theta - peaks[j].pose.theta) <= 0.1 + 1e-9;
      EXPECT_FALSE(near) << i << " " << j;
    }
}

TEST(CorrelativeSearch, ThePriorDecidesWhereTheScanCannot) {
  // Two parallel walls: along x every pose fits; the prior keeps the predicted x.
  std::vector<V> walls;
  for (int k = -60; k <= 60; ++k) {
    walls.emplace_back(0.1 * k, 1.0);
    walls.emplace_back(0.1 * k, -1.0);
  }
  DistanceField f(0.05, 0.15);
  f.insert(walls);
  std::vector<V> scan;
  for (int k = -20; k <= 20; ++k) {
    scan.emplace_back(0.1 * k, 1.0);
    scan.emplace_back(0.1 * k, -1.0);
  }
  const PosePrior prior{slam::Pose2{0.1, 0.0, 0.0}, 0.5, 0.3, 0.01};
  const SearchResult r =
      correlative_search(f, scan, slam::Pose2{0.1, 0.0, 0.0}, {0.5, 0.1, 0.02}, prior);
  EXPECT_NEAR(r.pose.x, 0.1, 1e-9);
  EXPECT_NEAR(r.pose.y, 0.0, 1e-9);
}

TEST(BranchAndBound, FindsTheBruteForceBestAndHonoursTheExclusion) {
  aco::Rng rng(11);
  DistanceField f(0.1, 0.3);
  const slam::Pose2 truth{0.7, -0.4, 0.12};
  f.insert(placed(truth, shape()));
  f.insert(random_points(rng, 15, 4.0));  // clutter
  const LikelihoodPyramid pyramid(f, 0.1, 4);
  const SearchBox box{slam::Pose2{0.0, 0.0, 0.0}, 1.0, 0.8, 0.2, 0.04};
  const std::optional<ScoredPose> found = branch_and_bound(pyramid, shape(), box, 0.0);
  ASSERT_TRUE(found.has_value());
  ScoredPose brute{{}, -1.0};
  ScoredPose second{{}, -1.0};
  const Exclusion exclusion{found->pose, 0.3, 0.1};
  for (int k = -5; k <= 5; ++k)
    for (int dy = -8; dy <= 8; ++dy)
      for (int dx = -10; dx <= 10; ++dx) {
        const slam::Pose2 p{0.1 * dx, 0.1 * dy, slam::wrap_angle(0.04 * k)};
        const double s = lattice_score(pyramid, shape(), p);
        if (s > brute.score) brute = {p, s};
        const bool excluded = std::abs(p.x - exclusion.pose.x) <= 0.3 &&
                              std::abs(p.y - exclusion.pose.y) <= 0.3 &&
                              std::abs(p.theta - exclusion.pose.theta) <= 0.1;
        if (!excluded && s > second.score) second = {p, s};
      }
  EXPECT_NEAR(found->score, brute.score, 1e-9);
  EXPECT_NEAR(found->pose.x, truth.x, 0.051);
  EXPECT_NEAR(found->pose.y, truth.y, 0.051);
  EXPECT_NEAR(found->pose.theta, truth.theta, 0.021);
  const std::optional<ScoredPose> other = branch_and_bound(pyramid, shape(), box, 0.0, exclusion);
  ASSERT_TRUE(other.has_value());
  EXPECT_NEAR(other->score, second.score, 1e-9);
  // Nothing above the best exists.
  EXPECT_FALSE(branch_and_bound(pyramid, shape(), box, found->score + 1e-6).has_value());
}

}  // namespace
}  // namespace antslam::frontend
