// Loop closures: the matcher alone, and detection in a simulated loop.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "antslam/frontend/frontend.hpp"
#include "antslam/frontend/loop_closure.hpp"
#include "antslam/frontend/scan_matcher.hpp"
#include "antslam/frontend/simulator.hpp"

namespace antslam::frontend {
namespace {

using V = Eigen::Vector2d;

/// The points of scans taken along a path, in the frame of the path's first pose.
Points fragment_points(const World& world, const std::vector<slam::Pose2>& poses, bool dense,
                       std::uint64_t seed) {
  SimulationSettings sim;
  aco::Rng rng(seed);
  const ScanMatcherSettings s;
  Points out;
  for (const slam::Pose2& p : poses) {
    const LaserScan scan = simulate_scan(world, p, sim, rng);
    const ScanSurfaces surfaces = scan_surfaces(scan, 0.1, 20.0, s.surface_incidence);
    const Points local = dense ? dense_points(surfaces, 0.05) : supported_points(surfaces);
    for (const V& q : transform_points(slam::between(poses.front(), p), local)) out.push_back(q);
  }
  return thin_points(out, dense ? 0.1 : 0.1);
}

std::vector<slam::Pose2> straight(const slam::Pose2& start, int steps, double step) {
  std::vector<slam::Pose2> out;
  for (int k = 0; k < steps; ++k) out.push_back(start * slam::Pose2{step * k, 0.0, 0.0});
  return out;
}

TEST(LoopClosure, AcceptsTheTrueAlignmentFromAnOffsetPrior) {
  const World world = loop_world();
  const LoopClosureSettings settings;
  // Fragment a: the bottom corridor driven east; fragment b: the same stretch driven again,
  // starting 0.6 m further, slightly off the centre line.
  const std::vector<slam::Pose2> a = straight({1.0, 0.0, 0.0}, 16, 0.3);
  const std::vector<slam::Pose2> b = straight({1.6, 0.2, 0.05}, 16, 0.3);
  const FragmentMap target(fragment_points(world, a, true, 1), settings);
  const Points source = fragment_points(world, b, false, 2);
  const slam::Pose2 truth = slam::between(a.front(), b.front());
  const slam::Pose2 prior = truth * slam::Pose2{0.5, -0.4, 0.08};  // the chain drifted
  const Eigen::Matrix3d prior_cov = Eigen::Vector3d(0.09, 0.09, 0.004).asDiagonal();
  const slam::Pose2 anchor = slam::between(b.front(), b.back());
  const ClosureMatch m = match_fragments(target, source, prior, prior_cov, anchor, settings);
  ASSERT_TRUE(m.accepted) << m.reason;
  EXPECT_NEAR(m.pose.x, truth.x, 0.03);
  EXPECT_NEAR(m.pose.y, truth.y, 0.03);
  EXPECT_NEAR(m.pose.theta, truth.theta, 0.01);
  EXPECT_GT(m.score, settings.min_score);
  // N(mu_H, Sigma_H) is over the anchor's pose in F_a and holds the truth.
  const slam::Pose2 true_anchor = truth * anchor;
  EXPECT_NEAR(m.anchored->mean().x, true_anchor.x, 0.05);
  EXPECT_LT(m.anchored->mahalanobis_squared(true_anchor), 20.0);
  EXPECT_LT(m.relative->mahalanobis_squared(truth), 20.0);
}

TEST(LoopClosure, RejectsAPlaceThatDoesNotMatch) {
  const World world = loop_world();
  const LoopClosureSettings settings;
  // a: the bottom corridor (2.4 m wide); b: the right one (3 m wide, with a bay), which the
  // prior claims is the bottom one.
  const std::vector<slam::Pose2> a = straight({2.0, 0.0, 0.0}, 16, 0.3);
  const std::vector<slam::Pose2> b = straight({20.0, 3.0, 1.5708}, 16, 0.3);
  const FragmentMap target(fragment_points(world, a, true, 3), settings);
  const ClosureMatch m =
      match_fragments(target, fragment_points(world, b, false, 4), slam::Pose2{0.0, 0.0, 0.0},
                      Eigen::Vector3d(0.1, 0.1, 0.01).asDiagonal(), slam::Pose2{}, settings);
  EXPECT_FALSE(m.accepted) << m.reason;
  EXPECT_LT(m.score, 0.8 * settings.min_score);
}

TEST(LoopClosure, RejectsACorridorThatMatchesItselfShifted) {
  const World world = corridor_world();
  const LoopClosureSettings settings;
  const std::vector<slam::Pose2> a = straight({-5.0, 0.0, 0.0}, 30, 0.3);
  const std::vector<slam::Pose2> b = straight({-3.0, 0.1, 0.0}, 16, 0.3);
  const FragmentMap target(fragment_points(world, a, true, 5), settings);
  const slam::Pose2 truth = slam::between(a.front(), b.front());
  const ClosureMatch m =
      match_fragments(target, fragment_points(world, b, false, 6), truth,
                      Eigen::Vector3d(1.0, 0.04, 0.004).asDiagonal(), slam::Pose2{}, settings);
  EXPECT_FALSE(m.accepted);
  EXPECT_GT(m.score, settings.min_score);                          // it fits well ...
  EXPECT_GT(m.second_score, settings.max_second_ratio * m.score);  // ... everywhere along
  EXPECT_NE(m.reason.find("ambiguous"), std::string::npos);
}

/// Once round the ring corridor and on past the start, where the loop closes.
SimulatedRun ring_loop_run() {
  SimulationSettings sim;
  sim.beams = 181;
  sim.step = 0.35;
  std::vector<V> path = loop_waypoints();
  path.push_back(V(8, 0));
  return simulate_run(loop_world(), path, sim, 4);
}

TEST(LoopClosure, TheFrontendClosesASimulatedLoop) {
  const SimulatedRun run = ring_loop_run();
  FrontendSettings settings;
  const FrontendResult r = run_frontend(run.log, settings);
  ASSERT_GE(r.fragment_set.closures.size(), 1U);
  EXPECT_NO_THROW(slam::validate(r.fragment_set));
  bool closes_the_loop = false;
  for (const ClosureAttempt& a : r.attempts) {
    if (!a.match.accepted) continue;
    // Every accepted closure is right: F_b in F_a as the truth has it.
    const slam::Pose2 truth = slam::between(run.truth[r.fragments[a.from].first_scan].pose,
                                            run.truth[r.fragments[a.to].first_scan].pose);
    EXPECT_NEAR(a.match.pose.x, truth.x, 0.1) << a.from << " -> " << a.to;
    EXPECT_NEAR(a.match.pose.y, truth.y, 0.1) << a.from << " -> " << a.to;
    EXPECT_NEAR(a.match.pose.theta, truth.theta, 0.02) << a.from << " -> " << a.to;
    closes_the_loop = closes_the_loop || a.from <= 1;
  }
  EXPECT_TRUE(closes_the_loop);
  for (const slam::LoopClosure& c : r.fragment_set.closures) {
    EXPECT_LT(c.from + settings.closure.min_fragment_gap, c.to + 1);
    EXPECT_NEAR(c.anchor.x, r.fragment_set.fragments[c.to].exit.x, 1e-12);  // anchor = E_b
  }
}

TEST(LoopClosure, NeighboursOfTheCandidateJoinItsMap) {
  // A later fragment seldom sees what one earlier fragment saw: matched against the candidate
  // and its neighbours, more revisits close, and every accepted match is still right.
  const SimulatedRun run = ring_loop_run();
  FrontendSettings alone;
  alone.closure.target_neighbours = 0;
  const FrontendResult single = run_frontend(run.log, alone);
  const FrontendResult joined = run_frontend(run.log, FrontendSettings{});
  const auto accepted = [](const FrontendResult& r) {
    std::size_t n = 0;
    for (const ClosureAttempt& a : r.attempts) n += a.match.accepted ? 1U : 0U;
    return n;
  };
  EXPECT_GT(accepted(joined), accepted(single));
}

}  // namespace
}  // namespace antslam::frontend
