// Fragmentation (paper Sec. III-A, eqs. (4) and (7)).
#include <gtest/gtest.h>

#include <cmath>

#include "antslam/frontend/fragmenter.hpp"
#include "antslam/frontend/pose_covariance.hpp"

namespace antslam::frontend {
namespace {

const Eigen::Matrix3d kStep = Eigen::Vector3d(1e-4, 4e-4, 1e-5).asDiagonal();

/// A robot driving along a quarter circle of radius 10 m in steps of 0.3 m.
slam::Pose2 on_arc(std::size_t k) {
  const double s = 0.3 * static_cast<double>(k), r = 10.0;
  return {r * std::sin(s / r), r - r * std::cos(s / r), s / r};
}

TEST(Fragmenter, CutsWheneverTheRobotHasTravelledTheLength) {
  FragmentationSettings settings;
  settings.length = 2.0;
  Fragmenter f(settings);
  std::vector<std::size_t> starts;
  for (std::size_t k = 0; k < 30; ++k)
    if (f.add(k, 0.1 * static_cast<double>(k), on_arc(k), kStep)) starts.push_back(k);
  // Chords of 0.3 m arcs are just under 0.3 m: 2 m are reached after 7 steps.
  const double chord = 2.0 * 10.0 * std::sin(0.3 / 20.0);
  const auto per_fragment = static_cast<std::size_t>(std::ceil(2.0 / chord));
  ASSERT_EQ(per_fragment, 7U);
  const std::vector<std::size_t> expected{0, 7, 14, 21, 28};
  EXPECT_EQ(starts, expected);
  const std::vector<FragmentRecord>& fr = f.fragments();
  ASSERT_EQ(fr.size(), 5U);
  EXPECT_EQ(fr[1].first_scan, 7U);
  EXPECT_EQ(fr[1].scan_count, 7U);
  EXPECT_EQ(fr[4].scan_count, 2U);
  EXPECT_NEAR(fr[0].length, 7 * chord, 1e-9);
  // Eq. (4): F_{i+1} = E_i; frames are the poses of the first scans.
  for (std::size_t i = 0; i + 1 < fr.size(); ++i) {
    const slam::Pose2 e = f.exit(i);
    const slam::Pose2 expected_exit = slam::between(on_arc(starts[i]), on_arc(starts[i + 1]));
    EXPECT_NEAR(e.x, expected_exit.x, 1e-12);
    EXPECT_NEAR(e.y, expected_exit.y, 1e-12);
    EXPECT_NEAR(e.theta, expected_exit.theta, 1e-12);
    EXPECT_NEAR((fr[i].frame * e).x, fr[i + 1].frame.x, 1e-12);
  }
  // Trajectories hold each fragment's poses in its own frame, starting at its origin.
  EXPECT_NEAR(fr[2].trajectory[0].pose.x, 0.0, 1e-12);
  EXPECT_NEAR(fr[2].trajectory[3].pose.theta, 0.09, 1e-12);
  EXPECT_DOUBLE_EQ(fr[2].trajectory[3].stamp, 1.7);
  // The last fragment's exit is its last pose.
  EXPECT_NEAR(f.exit(4).x, slam::between(on_arc(28), on_arc(29)).x, 1e-12);
}

TEST(Fragmenter, AlignmentGaussiansAndSamples) {
  FragmentationSettings settings;
  settings.length = 2.0;
  settings.samples = 500;
  settings.covariance_scale = 2.0;
  Fragmenter f(settings);
  for (std::size_t k = 0; k < 22; ++k) f.add(k, 0.0, on_arc(k), kStep);
  // The accumulated covariance of fragment 0: seven steps, each with this covariance in the
  // axes of the pose it starts from, composed in order.
  Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
  slam::Pose2 at;
  for (std::size_t k = 1; k <= 7; ++k) {
    const slam::Pose2 step = slam::between(on_arc(k - 1), on_arc(k));
    const Eigen::Matrix3d in_axes = compose_covariance(slam::Pose2{0, 0, -on_arc(k - 1).theta},
                                                       Eigen::Matrix3d::Zero(), {}, kStep);
    c = compose_covariance(at, c, step, in_axes);
    at = at * step;
  }
  EXPECT_LT((f.fragments()[0].accumulated - c).norm(), 1e-15);
  EXPECT_LT((f.exit_covariance(0) - 2.0 * c).norm(), 1e-15);

  const slam::FragmentSet set = f.fragment_set("arc");
  EXPECT_NO_THROW(slam::validate(slam::FragmentSet{set.name, set.fragments, {{0, 3, {}, {}}}, {}}));
  ASSERT_EQ(set.fragments.size(), 4U);
  EXPECT_FALSE(set.fragments[0].alignment.has_value());
  EXPECT_TRUE(set.fragments[0].samples.empty());
  for (std::size_t i = 1; i < 4; ++i) {
    const slam::Gaussian2& g = *set.fragments[i].alignment;
    EXPECT_NEAR(g.mean().x, f.exit(i - 1).x, 1e-12);  // mu_i = E_{i-1}
    ASSERT_EQ(set.fragments[i].samples.size(), 500U);
    // Eq. (7): the samples' spread is the Gaussian's.
    double mean_x = 0.0, var_x = 0.0;
    for (const slam::Pose2& s : set.fragments[i].samples) mean_x += s.x / 500.0;
    for (const slam::Pose2& s : set.fragments[i].samples)
      var_x += (s.x - mean_x) * (s.x - mean_x) / 500.0;
    EXPECT_NEAR(mean_x, g.mean().x, 4.0 * std::sqrt(g.covariance()(0, 0) / 500.0));
    EXPECT_NEAR(var_x, g.covariance()(0, 0), 0.2 * g.covariance()(0, 0));
  }
  // Same seed, same samples; another seed, others.
  EXPECT_EQ(f.fragment_set("again").fragments[2].samples[7].x, set.fragments[2].samples[7].x);
  FragmentationSettings other = settings;
  other.seed = 99;
  Fragmenter g(other);
  for (std::size_t k = 0; k < 22; ++k) g.add(k, 0.0, on_arc(k), kStep);
  EXPECT_NE(g.fragment_set("other").fragments[2].samples[7].x, set.fragments[2].samples[7].x);
}

TEST(Fragmenter, ExitScanModeUsesTheLeavingScansCovariance) {
  FragmentationSettings settings;
  settings.length = 2.0;
  settings.covariance = AlignmentCovariance::exit_scan;
  settings.covariance_scale = 1.0;
  Fragmenter f(settings);
  Eigen::Matrix3d last = kStep;
  for (std::size_t k = 0; k < 10; ++k) {
    last = (1.0 + static_cast<double>(k)) * kStep;
    f.add(k, 0.0, on_arc(k), last);
  }
  // Scan 7 left fragment 0: its covariance, turned into F_0 axes (F_0 heading is 0).
  EXPECT_LT((f.exit_covariance(0) - 8.0 * kStep).norm(), 1e-15);
}

TEST(Fragmenter, RejectsNonsenseSettings) {
  FragmentationSettings s;
  s.length = 0.0;
  EXPECT_THROW(Fragmenter{s}, std::invalid_argument);
  s = {};
  s.samples = 0;
  EXPECT_THROW(Fragmenter{s}, std::invalid_argument);
  s = {};
  s.covariance_scale = -1.0;
  EXPECT_THROW(Fragmenter{s}, std::invalid_argument);
}

}  // namespace
}  // namespace antslam::frontend
