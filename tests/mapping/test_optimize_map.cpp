// The pipeline (frontend -> fragment set -> optimizer -> corrected trajectory): closure
// residuals by hand, the corrected trajectory's composition, thread independence, and a
// simulated loop that the optimised map closes within every closure's 2-sigma ellipse.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "antslam/frontend/frontend.hpp"
#include "antslam/frontend/simulator.hpp"
#include "antslam/mapping/optimize_map.hpp"

namespace antslam::mapping {
namespace {

using namespace antslam::frontend;

using V = Eigen::Vector2d;

TEST(Mapping, ClosureResidualMatchesAHandComputation) {
  // Three fragments; closure 0 -> 2 with its anchor 1 m ahead of F_3's origin.
  slam::FragmentSet set;
  set.fragments.resize(3);
  const Eigen::Matrix3d cov = Eigen::Vector3d(0.01, 0.04, 0.0025).asDiagonal();
  set.closures.push_back(
      {0, 2, slam::Pose2{1, 0, 0},
       slam::Gaussian2(slam::Pose2{2.1, 1.8, std::numbers::pi / 2 + 0.05}, cov)});
  // F_3 at (2, 1, 90 deg): the anchor lands at (2, 2, 90 deg) in W = F_1.
  const std::vector<slam::Pose2> frames{{0, 0, 0}, {5, 5, 1}, {2, 1, std::numbers::pi / 2}};
  const std::vector<ClosureResidual> r = closure_residuals(set, frames);
  ASSERT_EQ(r.size(), 1U);
  EXPECT_EQ(r[0].from, 0U);
  EXPECT_EQ(r[0].to, 2U);
  EXPECT_NEAR(r[0].residual.x, -0.1, 1e-12);
  EXPECT_NEAR(r[0].residual.y, 0.2, 1e-12);
  EXPECT_NEAR(r[0].residual.theta, -0.05, 1e-12);
  // (0.1^2 / 0.01) + (0.2^2 / 0.04) + (0.05^2 / 0.0025) = 3.
  EXPECT_NEAR(r[0].mahalanobis, std::sqrt(3.0), 1e-9);
}

TEST(Mapping, ClosureResidualIsRelativeToTheEarlierFragment) {
  // Moving every frame by the same rigid motion changes nothing.
  slam::FragmentSet set;
  set.fragments.resize(2);
  set.closures.push_back({0, 1, slam::Pose2{0.5, -0.2, 0.1},
                          slam::Gaussian2(slam::Pose2{3, 1, 0.3}, Eigen::Matrix3d::Identity())});
  const std::vector<slam::Pose2> frames{{0, 0, 0}, {2.9, 1.1, 0.25}};
  const slam::Pose2 move{-4, 7, 2.0};
  const std::vector<slam::Pose2> moved{move * frames[0], move * frames[1]};
  const ClosureResidual a = closure_residuals(set, frames)[0];
  const ClosureResidual b = closure_residuals(set, moved)[0];
  EXPECT_NEAR(a.mahalanobis, b.mahalanobis, 1e-12);
  EXPECT_NEAR(a.residual.theta, b.residual.theta, 1e-12);
}

/// One lap of the simulated ring corridor and 8 m past the start (the loop closes there).
const FrontendResult& simulated_loop() {
  static const FrontendResult result = [] {
    SimulationSettings sim;
    sim.beams = 181;
    sim.step = 0.35;
    std::vector<V> path = loop_waypoints();
    path.push_back(V(8, 0));
    const SimulatedRun run = simulate_run(loop_world(), path, sim, 4);
    return run_frontend(run.log, FrontendSettings{});
  }();
  return result;
}

MappingSettings quick_settings() {
  MappingSettings s;
  s.trials = 3;
  s.optimize.iterations = 30;
  return s;
}

bool same_frames(const std::vector<slam::Pose2>& a, const std::vector<slam::Pose2>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].x != b[i].x || a[i].y != b[i].y || a[i].theta != b[i].theta) return false;
  return true;
}

TEST(Mapping, WithoutClosingTheMapIsTheBestTrial) {
  MappingSettings s = quick_settings();
  s.closing.enabled = false;
  const MappingResult r = optimize_map(simulated_loop().fragment_set, s);
  EXPECT_FALSE(r.closing.has_value());
  EXPECT_TRUE(same_frames(r.frames, r.trials[r.best].frames));
  EXPECT_NEAR(r.scores.weight, r.trials[r.best].scores.weight, 1e-9);
}

TEST(Mapping, OptimisedMapHonoursEveryClosureAndComposesTheTrajectory) {
  const FrontendResult& fr = simulated_loop();
  const slam::FragmentSet& set = fr.fragment_set;
  ASSERT_GE(set.closures.size(), 1U);
  const MappingResult r = optimize_map(set, quick_settings());
  ASSERT_EQ(r.trials.size(), 3U);
  for (const slam::OptimizeResult& t : r.trials)
    EXPECT_LE(r.trials[r.best].scores.weight, t.scores.weight);
  // Acceptance: every closure within its Gaussian's 2-sigma ellipse afterwards.
  ASSERT_EQ(r.after.size(), set.closures.size());
  for (const ClosureResidual& c : r.after) EXPECT_LE(c.mahalanobis, 2.0) << c.from << "-" << c.to;
  EXPECT_LT(r.trials[r.best].scores.weight, r.scan_matcher.weight);
  // The scan-matcher frames are the chain of the means (eq. 8) = the frontend's own frames.
  ASSERT_EQ(r.scan_matcher_frames.size(), fr.fragments.size());
  for (std::size_t i = 0; i < fr.fragments.size(); ++i) {
    EXPECT_NEAR(r.scan_matcher_frames[i].x, fr.fragments[i].frame.x, 1e-9);
    EXPECT_NEAR(r.scan_matcher_frames[i].y, fr.fragments[i].frame.y, 1e-9);
  }
  // The map: the loops closed with every (consistent) closure from the best trial.
  ASSERT_TRUE(r.closing.has_value());
  for (const bool trusted : r.closing->trusted) EXPECT_TRUE(trusted);
  EXPECT_TRUE(same_frames(r.frames, r.closing->frames));
  // Every scan: its fragment's map frame times its pose in the fragment, in scan order.
  ASSERT_EQ(r.corrected.size(), fr.trajectory.size());
  const std::vector<slam::Pose2>& frames = r.frames;
  for (std::size_t i = 0; i < fr.fragments.size(); ++i) {
    const FragmentRecord& f = fr.fragments[i];
    for (std::size_t k = 0; k < f.scan_count; ++k) {
      const slam::StampedPose& c = r.corrected[f.first_scan + k];
      const slam::Pose2 expected = frames[i] * f.trajectory[k].pose;
      EXPECT_EQ(c.stamp, fr.trajectory[f.first_scan + k].stamp);
      EXPECT_NEAR(c.pose.x, expected.x, 1e-9);
      EXPECT_NEAR(c.pose.y, expected.y, 1e-9);
      EXPECT_NEAR(slam::wrap_angle(c.pose.theta - expected.theta), 0.0, 1e-9);
    }
  }
}

TEST(Mapping, ResultDoesNotDependOnTheThreadCount) {
  const slam::FragmentSet& set = simulated_loop().fragment_set;
  MappingSettings s = quick_settings();
  s.threads = 1;
  const MappingResult one = optimize_map(set, s);
  s.threads = 2;
  std::size_t observed = 0;
  const MappingResult two = optimize_map(set, s, [&](std::size_t done) { observed = done; });
  EXPECT_EQ(observed, s.trials);
  EXPECT_EQ(one.best, two.best);
  ASSERT_EQ(one.trials.size(), two.trials.size());
  for (std::size_t t = 0; t < one.trials.size(); ++t)
    EXPECT_EQ(one.trials[t].scores.weight, two.trials[t].scores.weight);
  for (std::size_t k = 0; k < one.corrected.size(); k += 17)
    EXPECT_EQ(one.corrected[k].pose.x, two.corrected[k].pose.x);
}

TEST(Mapping, RejectsASetWithoutClosuresAndZeroTrials) {
  slam::FragmentSet set;
  set.name = "two.json";
  set.fragments.resize(2);
  set.fragments[1].alignment = slam::Gaussian2(slam::Pose2{1, 0, 0}, Eigen::Matrix3d::Identity());
  set.fragments[1].samples = {slam::Pose2{1, 0, 0}};
  set.closures.push_back(
      {0, 1, slam::Pose2{}, slam::Gaussian2(slam::Pose2{1, 0, 0}, Eigen::Matrix3d::Identity())});
  MappingSettings s = quick_settings();
  EXPECT_NO_THROW(optimize_map(set, s));
  s.trials = 0;
  EXPECT_THROW(optimize_map(set, s), std::invalid_argument);
  set.closures.clear();
  EXPECT_THROW(optimize_map(set, quick_settings()), std::invalid_argument);
}

TEST(Mapping, ValidatesTheOptimizerBeforeAnyWork) {
  MappingSettings s;
  EXPECT_NO_THROW(validate(s));
  s.optimize.aco.rho = 2.0;
  EXPECT_THROW(validate(s), std::invalid_argument);
  s = {};
  s.optimize.aco.ants = 1'000'000;
  EXPECT_THROW(validate(s), std::invalid_argument);
  s = {};
  s.optimize.refine.max_evaluations = 0;
  EXPECT_THROW(validate(s), std::invalid_argument);
  s = {};
  s.optimize.iterations = 0;
  EXPECT_THROW(validate(s), std::invalid_argument);
}

}  // namespace
}  // namespace antslam::mapping
