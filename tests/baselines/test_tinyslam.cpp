#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "antslam/baselines/tinyslam.hpp"
#include "antslam/eval/evaluation.hpp"
#include "antslam/frontend/simulator.hpp"

namespace antslam::baselines {
namespace {

using V = Eigen::Vector2d;

frontend::SimulationSettings room_simulation() {
  frontend::SimulationSettings sim;
  sim.beams = 181;
  sim.step = 0.2;
  sim.max_range = 10.0;
  return sim;
}

TEST(TinySlam, ScanPointsUseTheLaserPoseAndDropUnusableReadings) {
  frontend::LaserScan scan;
  scan.first_angle = 0.0;
  scan.angle_step = 1.5707963267948966;
  scan.max_range = 8.0;
  scan.laser_pose = {0.5, 0.0, 0.0};
  scan.ranges = {2.0F, 8.0F, 0.05F};  // a hit ahead, a no-return, a reading on the robot
  const std::vector<V> points = scan_points(scan, TinySlamSettings{});
  ASSERT_EQ(points.size(), 1U);
  EXPECT_NEAR(points[0].x(), 2.5, 1e-12);
  EXPECT_NEAR(points[0].y(), 0.0, 1e-12);
}

TEST(TinySlam, CorrespondenceIsTheMeanOccupancyOfThePointsCells) {
  OccupancyGrid map(0.1);
  map.update(10, 0, 1.0, 1.0);   // cell of (1.05, 0.05)
  map.update(0, 20, 1.0, 0.25);  // cell of (0.05, 2.05)
  const std::vector<V> points{V(1.05, 0.05), V(0.05, 2.05), V(-3.0, -3.0)};
  EXPECT_NEAR(correspondence(map, points, {}), (1.0 + 0.25 + 0.5) / 3.0, 1e-7);
  // Turned by 90 degrees, the first point lands in the cell of (-0.05, 1.05): unknown.
  const std::vector<V> one{V(1.05, 0.05)};
  EXPECT_NEAR(correspondence(map, one, {0.0, 0.0, 1.5707963267948966}), 0.5, 1e-7);
}

TEST(TinySlam, MonteCarloSearchFindsAScanThatWasMoved) {
  const frontend::World room = frontend::room_world();
  const frontend::SimulationSettings sim = room_simulation();
  aco::Rng noise(2);
  const slam::Pose2 truth{0.3, -0.4, 0.2};
  const frontend::LaserScan scan = frontend::simulate_scan(room, truth, sim, noise);
  TinySlamSettings s;
  const std::vector<V> points = scan_points(scan, s);
  OccupancyGrid map(s.resolution);
  for (int k = 0; k < 5; ++k)
    for (const V& p : points) map.insert_beam(truth.translation(), truth * p, 0.5, s.hole_width);
  aco::Rng rng(3);
  const slam::Pose2 start{truth.x + 0.15, truth.y - 0.1, truth.theta + 0.06};
  const SearchResult found = monte_carlo_search(map, points, start, s, rng);
  EXPECT_NEAR(found.pose.x, truth.x, 0.03);
  EXPECT_NEAR(found.pose.y, truth.y, 0.03);
  EXPECT_NEAR(found.pose.theta, truth.theta, 0.01);
  EXPECT_GT(found.score, correspondence(map, points, start));
  EXPECT_GE(found.evaluations, s.stop);
}

struct RoomRun {
  frontend::SimulatedRun run;
  TinySlamResult result;
};

RoomRun map_the_room(std::uint64_t seed) {
  const std::vector<V> path{V(-1, -0.5), V(3.2, -0.5), V(3.2, 2.2), V(-1.8, 2.2), V(-1, -0.5)};
  frontend::SimulatedRun run =
      frontend::simulate_run(frontend::room_world(), path, room_simulation(), 17);
  TinySlamSettings s;
  s.seed = seed;
  s.stop = 300;
  TinySlamResult result = run_tinyslam(run.log, s);
  return {std::move(run), std::move(result)};
}

double rmse(const slam::Trajectory& estimate, const slam::Trajectory& truth) {
  eval::EvaluationSettings s;
  s.align = false;  // both start at the true first pose
  return eval::evaluate(estimate, truth, s).ate.translation_m.rmse;
}

TEST(TinySlam, MapsASimulatedRoom) {
  const RoomRun r = map_the_room(1);
  ASSERT_EQ(r.result.trajectory.size(), r.run.truth.size());
  slam::Trajectory odometry;
  for (const frontend::LaserScan& scan : r.run.log.scans)
    odometry.push_back({scan.stamp, scan.odometry});
  const double mapped = rmse(r.result.trajectory, r.run.truth);
  const double odometry_only = rmse(odometry, r.run.truth);
  EXPECT_LT(mapped, 0.05);
  EXPECT_LT(mapped, odometry_only / 3.0) << "odometry alone: " << odometry_only;
  EXPECT_EQ(r.result.unmatched, 0U);

  // The walls are occupied and the middle of the room is free.
  double wall = 0.0;
  int wall_cells = 0;
  for (double x = -3.5; x <= 3.5; x += 0.1) {
    wall += r.result.map.at(V(x, -3.0 + 0.01));
    wall += r.result.map.at(V(x, -3.0 - 0.01));
    wall_cells += 2;
  }
  EXPECT_GT(wall / wall_cells, 0.35);  // blurred across two cells, mostly above the free level
  for (const V& p : {V(0.0, 0.5), V(-1.0, 1.2), V(2.5, 0.8)})
    EXPECT_LT(r.result.map.at(p), 0.1) << p.transpose();
}

TEST(TinySlam, SameSeedSameTrajectory) {
  const RoomRun a = map_the_room(4), b = map_the_room(4);
  ASSERT_EQ(a.result.trajectory.size(), b.result.trajectory.size());
  for (std::size_t i = 0; i < a.result.trajectory.size(); ++i) {
    EXPECT_EQ(a.result.trajectory[i].pose.x, b.result.trajectory[i].pose.x);
    EXPECT_EQ(a.result.trajectory[i].pose.theta, b.result.trajectory[i].pose.theta);
  }
  EXPECT_EQ(a.result.evaluations, b.result.evaluations);
}

TEST(TinySlam, RejectsNonsenseSettings) {
  TinySlamSettings s;
  s.quality = 0.0;
  try {
    validate(s);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "tinyslam: quality must be in (0, 1]");
  }
  s = {};
  s.sigma_xy = NAN;
  EXPECT_THROW(TinySlam{s}, std::invalid_argument);
  s = {};
  s.min_range = 30.0;
  EXPECT_THROW(validate(s), std::invalid_argument);
}

}  // namespace
}  // namespace antslam::baselines
