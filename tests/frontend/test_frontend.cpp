// The whole frontend: bookkeeping, determinism, settings.
#include <gtest/gtest.h>

#include <vector>

#include "antslam/frontend/frontend.hpp"
#include "antslam/frontend/map_render.hpp"
#include "antslam/frontend/report.hpp"
#include "antslam/frontend/simulator.hpp"

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

TEST(Frontend, ObserverSeesEveryScanAndTheFinalCounts) {
  const SimulatedRun run = small_run();
  FrontendSettings s;
  s.fragmentation.length = 3.0;
  std::vector<FrontendProgress> seen;
  const FrontendResult r =
      run_frontend(run.log, s, [&](const FrontendProgress& p) { seen.push_back(p); });
  ASSERT_EQ(seen.size(), run.log.scans.size());
  for (std::size_t i = 0; i < seen.size(); ++i) {
    EXPECT_EQ(seen[i].scan, i + 1);
    EXPECT_EQ(seen[i].scans, run.log.scans.size());
  }
  EXPECT_EQ(seen.back().fragments, r.fragments.size());
  EXPECT_EQ(to_string(FrontendProgress{12, 225, 3, 1}),
            "frontend: scan 12/225, fragments 3, closures 1");
}

TEST(Frontend, ReportNamesTheAlignmentAndHoldsEveryFragment) {
  for (const AlignmentCovariance c :
       {AlignmentCovariance::accumulated, AlignmentCovariance::exit_scan})
    EXPECT_EQ(parse_alignment_covariance(to_string(c)), c);
  EXPECT_THROW(parse_alignment_covariance("exit"), std::invalid_argument);
  const SimulatedRun run = small_run();
  FrontendSettings s;
  s.fragmentation.length = 3.0;
  s.fragmentation.covariance = AlignmentCovariance::exit_scan;
  const FrontendResult r = run_frontend(run.log, s);
  const nlohmann::json input = input_json("run.clf", run.log, s, MapRenderSettings{});
  EXPECT_EQ(input["settings"]["alignment"], "exit-scan");
  EXPECT_EQ(input["scans"], run.log.scans.size());
  const nlohmann::json result = result_json(r);
  EXPECT_EQ(result["fragments"].size(), r.fragments.size());
  EXPECT_EQ(result["fragments"][1]["first_scan"], r.fragments[1].first_scan);
}

TEST(Frontend, SampleAverageMapIsSeeded) {
  const SimulatedRun run = small_run();
  FrontendSettings s;
  s.fragmentation.length = 3.0;
  const FrontendResult r = run_frontend(run.log, s);
  MapRenderSettings m;
  m.resolution = 0.25;
  const Image a = render_sample_average_map(run.log, r, 4, 7, m);
  const Image b = render_sample_average_map(run.log, r, 4, 7, m);
  const Image c = render_sample_average_map(run.log, r, 4, 8, m);
  ASSERT_EQ(a.width(), b.width());
  ASSERT_EQ(a.height(), b.height());
  std::size_t same = 0, differ = 0;
  for (std::size_t y = 0; y < a.height(); ++y)
    for (std::size_t x = 0; x < a.width(); ++x) same += a.at(x, y) == b.at(x, y) ? 1U : 0U;
  EXPECT_EQ(same, a.width() * a.height());
  const bool same_size = c.width() == a.width() && c.height() == a.height();
  if (same_size)
    for (std::size_t y = 0; y < a.height(); ++y)
      for (std::size_t x = 0; x < a.width(); ++x) differ += a.at(x, y) == c.at(x, y) ? 0U : 1U;
  EXPECT_TRUE(!same_size || differ > 0);
  EXPECT_THROW(render_sample_average_map(run.log, r, 0, 7, m), std::invalid_argument);
}

}  // namespace
}  // namespace antslam::frontend
