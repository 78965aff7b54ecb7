// Trajectory error against a reference, and the readers for reference poses.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "slamgraph/evaluation.hpp"

namespace antslam::slam {
namespace {

TEST(TrajectoryError, RigidMotionCostsNothing) {
  const std::vector<Pose2> reference{{0, 0, 0}, {1, 0, 0.1}, {2, 1, 0.5}, {1, 3, 2.0}};
  const Pose2 motion{5.0, -2.0, 1.2};
  std::vector<Pose2> moved;
  for (const Pose2& p : reference) moved.push_back(motion * p);
  const TrajectoryError e = absolute_trajectory_error(moved, reference);
  EXPECT_NEAR(e.rmse_m, 0.0, 1e-12);
  EXPECT_NEAR(e.rmse_rad, 0.0, 1e-12);
  EXPECT_EQ(e.poses, 4U);
}

// Two points symmetric about the centroid, one moved along their line by d: the best rotation
// is zero, the centroid moves by d/2, so both errors are d/2.
TEST(TrajectoryError, HandComputed) {
  const std::vector<Pose2> reference{{-1, 0, 0}, {1, 0, 0}};
  const std::vector<Pose2> estimate{{-1, 0, 0}, {1.4, 0, 0}};
  const TrajectoryError e = absolute_trajectory_error(estimate, reference);
  EXPECT_NEAR(e.rmse_m, 0.2, 1e-12);
  EXPECT_NEAR(e.max_m, 0.2, 1e-12);
  EXPECT_THROW(absolute_trajectory_error(estimate, std::vector<Pose2>(3)), std::invalid_argument);
}

TEST(ReferencePoses, ReadsXyThetaLinesAndG2o) {
  const auto gt = read_reference_poses(ANTSLAM_DATA_DIR "/posegraphs/manhattan3500.gt.dat");
  EXPECT_EQ(gt.size(), 3500U);
  EXPECT_EQ(gt[1].x, 1.0);
  EXPECT_EQ(read_reference_poses(ANTSLAM_DATA_DIR "/posegraphs/ring.gt.g2o").size(), 434U);
  std::filesystem::create_directories(ANTSLAM_TEST_TMP);
  const std::string bad = ANTSLAM_TEST_TMP "/bad.dat";
  std::ofstream(bad) << "1 2 3\n4 5\n";
  try {
    read_reference_poses(bad);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), bad + ":2: expected `x y theta`");
  }
}

}  // namespace
}  // namespace antslam::slam
