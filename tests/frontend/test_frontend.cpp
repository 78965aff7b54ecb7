// The whole frontend: bookkeeping, determinism, settings.
#include <gtest/gtest.h>

#include <vector>

#include "frontend/frontend.hpp"
#include "frontend/simulator.hpp"

namespace antslam::frontend {
namespace {

using V = Eigen::Vector2d;

SimulatedRun small_run() {
  SimulationSettings sim;
  sim.beams = 181;
  sim.step = 0.4;
  const std::vector<V> path{V(0, 0), V(20, 0), V(20, 8)};
  return simulate_run(loop_world(), path, sim, 21);
}

TEST(Frontend, EveryScanIsInExactlyOneFragment) {
  const SimulatedRun run = small_run();
  FrontendSettings s;
  s.fragmentation.length = 3.0;
  const FrontendResult r = run_frontend(run.log, s);
  ASSERT_EQ(r.trajectory.size(), run.log.scans.size());
  EXPECT_EQ(r.stats.scans, run.log.scans.size());
  std::size_t next = 0;
  for (std::size_t i = 0; i < r.fragments.size(); ++i) {
    const FragmentRecord& f = r.fragments[i];
    EXPECT_EQ(f.first_scan, next);
    EXPECT_EQ(f.trajectory.size(), f.scan_count);
    // The fragment's trajectory is the matcher's trajectory seen from the fragment's frame.
    for (std::size_t k = 0; k < f.scan_count; ++k) {
      const slam::Pose2 world = f.frame * f.trajectory[k].pose;
      EXPECT_NEAR(world.x, r.trajectory[f.first_scan + k].pose.x, 1e-9);
      EXPECT_NEAR(world.y, r.trajectory[f.first_scan + k].pose.y, 1e-9);
    }
    next += f.scan_count;
  }
  EXPECT_EQ(next, run.log.scans.size());
  EXPECT_EQ(r.fragment_set.fragments.size(), r.fragments.size());
  // 28 m of path in 3 m fragments.
  EXPECT_GE(r.fragments.size(), 9U);
  EXPECT_LE(r.fragments.size(), 10U);
  // The first pose is the origin of W (F_1 = W).
  EXPECT_EQ(r.trajectory[0].pose.x, 0.0);
  EXPECT_EQ(r.fragments[0].frame.theta, 0.0);
}

TEST(Frontend, SameInputSameOutput) {
  const SimulatedRun run = small_run();
  FrontendSettings s;
  s.fragmentation.length = 3.0;
  const FrontendResult a = run_frontend(run.log, s);
  const FrontendResult b = run_frontend(run.log, s);
  ASSERT_EQ(a.trajectory.size(), b.trajectory.size());
  for (std::size_t k = 0; k < a.trajectory.size(); ++k) {
    EXPECT_EQ(a.trajectory[k].pose.x, b.trajectory[k].pose.x);
    EXPECT_EQ(a.trajectory[k].pose.theta, b.trajectory[k].pose.theta);
  }
  ASSERT_EQ(a.fragment_set.fragments.size(), b.fragment_set.fragments.size());
  for (std::size_t i = 1; i < a.fragment_set.fragments.size(); ++i)
    EXPECT_EQ(a.fragment_set.fragments[i].samples[3].y, b.fragment_set.fragments[i].samples[3].y);
  ASSERT_EQ(a.attempts.size(), b.attempts.size());
}

TEST(Frontend, RejectsNonsenseSettingsBeforeWork) {
  FrontendSettings s;
  s.closure.min_score = 2.0;
  EXPECT_THROW(Frontend(s, "x"), std::invalid_argument);
  s = {};
  s.fragmentation.length = -1.0;
  EXPECT_THROW(Frontend(s, "x"), std::invalid_argument);
  s = {};
  s.matcher.max_range = 0.0;
  EXPECT_THROW(Frontend(s, "x"), std::invalid_argument);
}

}  // namespace
}  // namespace antslam::frontend
