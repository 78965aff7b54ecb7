// The corrected trajectory the experiments score (`antslam fragment-set` then `antslam optimize
// --tum-out`): every scan's pose is its fragment's world frame times its pose in that fragment.
// With the scan matcher's own frames it must give back the scan matcher's trajectory, and the
// fragment set file must carry those per-fragment poses.
#include <gtest/gtest.h>

#include <sstream>
#include <vector>

#include "antslam/frontend/frontend.hpp"
#include "antslam/frontend/map_render.hpp"
#include "antslam/frontend/simulator.hpp"
#include "antslam/slamgraph/fragment_set.hpp"
#include "antslam/slamgraph/fragment_set_io.hpp"

namespace antslam::frontend {
namespace {

FrontendResult small_frontend_run() {
  SimulationSettings sim;
  sim.beams = 181;
  sim.step = 0.4;
  const std::vector<Eigen::Vector2d> path{{0, 0}, {20, 0}, {20, 8}};
  FrontendSettings s;
  s.fragmentation.length = 3.0;
  return run_frontend(simulate_run(loop_world(), path, sim, 21).log, s);
}

TEST(CorrectedTrajectory, ScanMatcherFramesGiveBackTheScanMatcherTrajectory) {
  const FrontendResult r = small_frontend_run();
  ASSERT_GE(r.fragments.size(), 9U);
  const slam::Trajectory rebuilt = slam::world_trajectory(r.fragment_set, scan_matcher_frames(r));
  ASSERT_EQ(rebuilt.size(), r.trajectory.size());  // every scan exactly once
  for (std::size_t i = 0; i < rebuilt.size(); ++i) {
    EXPECT_EQ(rebuilt[i].stamp, r.trajectory[i].stamp) << "scan " << i;
    EXPECT_NEAR(rebuilt[i].pose.x, r.trajectory[i].pose.x, 1e-9) << "scan " << i;
    EXPECT_NEAR(rebuilt[i].pose.y, r.trajectory[i].pose.y, 1e-9) << "scan " << i;
    EXPECT_NEAR(slam::wrap_angle(rebuilt[i].pose.theta - r.trajectory[i].pose.theta), 0.0, 1e-9)
        << "scan " << i;
  }
}

TEST(CorrectedTrajectory, MovingOneFrameMovesExactlyItsScans) {
  const FrontendResult r = small_frontend_run();
  std::vector<slam::Pose2> frames = scan_matcher_frames(r);
  const std::size_t moved = 4;
  frames[moved].x += 1.5;  // a pure shift of F_5 in W shifts its scans by the same amount
  const slam::Trajectory rebuilt = slam::world_trajectory(r.fragment_set, frames);
  std::size_t scan = 0;
  for (std::size_t f = 0; f < r.fragments.size(); ++f)
    for (std::size_t k = 0; k < r.fragment_set.fragments[f].trajectory.size(); ++k, ++scan)
      EXPECT_NEAR(rebuilt[scan].pose.x - r.trajectory[scan].pose.x, f == moved ? 1.5 : 0.0, 1e-9)
          << "fragment " << f << ", scan " << scan;
  EXPECT_EQ(scan, r.trajectory.size());
}

TEST(CorrectedTrajectory, FragmentSetFileKeepsTheScanPoses) {
  FrontendResult r = small_frontend_run();
  if (r.fragment_set.closures.empty())  // the file format needs one; any valid closure will do
    r.fragment_set.closures.push_back(
        {0, r.fragments.size() - 1, slam::Pose2{}, slam::Gaussian2{}});
  std::stringstream file;
  slam::write_fragment_set(file, r.fragment_set);
  const slam::FragmentSet read = slam::read_fragment_set(file, "set.json");
  ASSERT_EQ(read.fragments.size(), r.fragment_set.fragments.size());
  for (std::size_t f = 0; f < read.fragments.size(); ++f) {
    const slam::Trajectory& a = read.fragments[f].trajectory;
    const slam::Trajectory& b = r.fragment_set.fragments[f].trajectory;
    ASSERT_EQ(a.size(), b.size()) << "fragment " << f;
    for (std::size_t k = 0; k < a.size(); ++k) {
      EXPECT_NEAR(a[k].stamp, b[k].stamp, 1e-6);
      EXPECT_NEAR(a[k].pose.x, b[k].pose.x, 1e-9);
      EXPECT_NEAR(a[k].pose.theta, b[k].pose.theta, 1e-9);
    }
  }
}

}  // namespace
}  // namespace antslam::frontend
