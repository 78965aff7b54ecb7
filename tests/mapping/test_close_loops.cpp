// Closing the loops with the trusted closures (mapping/close_loops.hpp): with consistent
// closures it is least squares on the whole set (Ceres'), a false closure is distrusted and the
// map follows the true ones, and a true closure far from a drifted map is trusted and closed.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "mapping/close_loops.hpp"
#include "slamgraph/synth.hpp"

namespace antslam::mapping {
namespace {

/// Two laps of the paper's rectangle, 24 fragments: several true revisit closures.
slam::FragmentSet two_laps() {
  slam::SynthSettings s = slam::synth_preset("paper24");
  s.laps = 2;
  s.seed = 3;
  return slam::synthesize(s);
}

double mahalanobis(const slam::LoopClosure& c, const std::vector<slam::Pose2>& frames) {
  return std::sqrt(c.hypothesis.mahalanobis_squared(slam::closure_pose(c, frames)));
}

TEST(CloseLoops, ConsistentClosuresAreAllTrustedAndSolvedByLeastSquares) {
  const slam::FragmentSet set = two_laps();
  ASSERT_GE(set.closures.size(), 3U);
  const std::vector<slam::Pose2> start = slam::chain(slam::mean_alignments(set));
  const Closing c = close_loops(set, start);
  EXPECT_EQ(c.solves, 1U);
  for (const bool t : c.trusted) EXPECT_TRUE(t);
  const slam::CeresResult ceres =
      slam::optimize_with_ceres(set, slam::mean_alignments(set), false, {});
  ASSERT_EQ(c.frames.size(), ceres.frames.size());
  for (std::size_t i = 0; i < c.frames.size(); ++i) {
    EXPECT_NEAR(c.frames[i].x, ceres.frames[i].x, 1e-6);
    EXPECT_NEAR(c.frames[i].theta, ceres.frames[i].theta, 1e-8);
  }
}

TEST(CloseLoops, AFalseClosureIsDistrustedAndTheMapFollowsTheTrueOnes) {
  slam::FragmentSet set = two_laps();
  const std::size_t true_closures = set.closures.size();
  // A false closure: fragment 20 said to be 4 m off where fragment 8 sees it, confidently.
  slam::LoopClosure wrong = set.closures.front();
  wrong.from = 8;
  wrong.to = 20;
  const slam::Pose2 truth = slam::closure_pose(wrong, set.reference);
  wrong.hypothesis = slam::Gaussian2(truth * slam::Pose2{4.0, 0.0, 0.0},
                                     Eigen::Vector3d(0.0025, 0.0025, 1e-4).asDiagonal());
  set.closures.push_back(wrong);
  const Closing c = close_loops(set, slam::chain(slam::mean_alignments(set)));
  EXPECT_FALSE(c.trusted.back());
  for (std::size_t k = 0; k < true_closures; ++k) EXPECT_TRUE(c.trusted[k]) << k;
  EXPECT_EQ(c.solves, 2U);
  // The true closures hold, the false one does not.
  for (std::size_t k = 0; k < true_closures; ++k)
    EXPECT_LT(mahalanobis(set.closures[k], c.frames), 3.4);
  EXPECT_GT(mahalanobis(set.closures.back(), c.frames), 20.0);
}

TEST(CloseLoops, ATrueClosureFarFromADriftedMapIsTrustedAndClosed) {
  slam::FragmentSet set = two_laps();
  // The scan matcher turned 1 degree too far at every fragment: after a lap the map is metres
  // off and every closure lies tens of standard deviations away from the means' map. Each
  // alignment's covariance is kept: the drift is what the alignments must absorb together.
  for (std::size_t i = 1; i < set.fragments.size(); ++i) {
    slam::Gaussian2& g = *set.fragments[i].alignment;
    slam::Pose2 mu = g.mean();
    mu.theta = slam::wrap_angle(mu.theta + 0.0175);
    g = slam::Gaussian2(mu, g.covariance());
  }
  const std::vector<slam::Pose2> start = slam::chain(slam::mean_alignments(set));
  double farthest = 0.0;
  for (const slam::LoopClosure& k : set.closures)
    farthest = std::max(farthest, mahalanobis(k, start));
  ASSERT_GT(farthest, 20.0);
  const Closing c = close_loops(set, start);
  for (std::size_t k = 0; k < set.closures.size(); ++k) {
    EXPECT_TRUE(c.trusted[k]) << k;
    EXPECT_LT(mahalanobis(set.closures[k], c.frames), std::sqrt(11.345)) << k;
  }
}

TEST(CloseLoops, NoTrustedClosureLeavesTheMeansAndBadInputIsRejected) {
  slam::FragmentSet set = two_laps();
  ClosingSettings strict;
  strict.outlier_chi2 = 1e-12;  // no closure can pass: each is distrusted in turn
  const Closing c = close_loops(set, slam::chain(slam::mean_alignments(set)), strict);
  for (const bool t : c.trusted) EXPECT_FALSE(t);
  EXPECT_EQ(c.solves, set.closures.size());
  const std::vector<slam::Pose2> means = slam::chain(slam::mean_alignments(set));
  for (std::size_t i = 0; i < means.size(); ++i) EXPECT_DOUBLE_EQ(c.frames[i].x, means[i].x);
  strict.outlier_chi2 = -1.0;
  EXPECT_THROW(close_loops(set, means, strict), std::invalid_argument);
  EXPECT_THROW(close_loops(set, std::vector<slam::Pose2>(3), {}), std::invalid_argument);
}

}  // namespace
}  // namespace antslam::mapping
