// Closing the loops with the trusted closures (mapping/close_loops.hpp): with consistent
// closures it is least squares on the whole set (Ceres'), a false closure is distrusted and the
// map follows the true ones (by every selection: iterative rejection and PCM, exact and by the
// ants), and a true closure far from a drifted map is trusted and closed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include "antslam/mapping/close_loops.hpp"
#include "antslam/slamgraph/synth.hpp"

namespace antslam::mapping {

void PrintTo(const ClosureSelectionInfo& info, std::ostream* os) { *os << info.name; }

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

/// The two laps with a false closure appended: fragment 20 said to be 4 m off where fragment 8
/// sees it, confidently.
slam::FragmentSet two_laps_with_a_false_closure() {
  slam::FragmentSet set = two_laps();
  slam::LoopClosure wrong = set.closures.front();
  wrong.from = 8;
  wrong.to = 20;
  const slam::Pose2 truth = slam::closure_pose(wrong, set.reference);
  wrong.hypothesis = slam::Gaussian2(truth * slam::Pose2{4.0, 0.0, 0.0},
                                     Eigen::Vector3d(0.0025, 0.0025, 1e-4).asDiagonal());
  set.closures.push_back(wrong);
  return set;
}

class EverySelection : public ::testing::TestWithParam<ClosureSelectionInfo> {};

TEST_P(EverySelection, DropsTheFalseClosureKeepsTheTrueOnesAndSolvesOverThem) {
  const slam::FragmentSet set = two_laps_with_a_false_closure();
  const std::size_t true_closures = set.closures.size() - 1;
  ClosingSettings settings;
  settings.selection = GetParam().value;
  const Closing c = close_loops(set, slam::chain(slam::mean_alignments(set)), settings);
  ASSERT_EQ(c.trusted.size(), set.closures.size());
  EXPECT_FALSE(c.trusted.back());
  for (std::size_t k = 0; k < true_closures; ++k) EXPECT_TRUE(c.trusted[k]) << k;
  // The map is least squares over the true closures alone.
  slam::FragmentSet truthful = set;
  truthful.closures.pop_back();
  const slam::CeresResult ceres =
      slam::optimize_with_ceres(truthful, slam::mean_alignments(set), false, {});
  ASSERT_EQ(c.frames.size(), ceres.frames.size());
  for (std::size_t i = 0; i < c.frames.size(); ++i) {
    EXPECT_NEAR(c.frames[i].x, ceres.frames[i].x, 1e-5) << i;
    EXPECT_NEAR(c.frames[i].y, ceres.frames[i].y, 1e-5) << i;
    EXPECT_NEAR(c.frames[i].theta, ceres.frames[i].theta, 1e-7) << i;
  }
  // The true closures hold, the false one does not.
  for (std::size_t k = 0; k < true_closures; ++k)
    EXPECT_LT(mahalanobis(set.closures[k], c.frames), 3.4);
  EXPECT_GT(mahalanobis(set.closures.back(), c.frames), 20.0);
  // PCM solves once, over the clique, which passes the joint check; the rejection solves again
  // after distrusting.
  const bool pcm = GetParam().value != ClosureSelection::iterative_chi2;
  EXPECT_EQ(c.solves, pcm ? 1U : 2U);
  ASSERT_EQ(c.clique.has_value(), pcm);
  if (pcm) {
    EXPECT_EQ(c.clique->clique.vertices.size(), true_closures);
  }
}

INSTANTIATE_TEST_SUITE_P(CloseLoops, EverySelection, ::testing::ValuesIn(kClosureSelections),
                         [](const auto& test) {
                           std::string name(test.param.name);
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(CloseLoops, SelectionNamesRoundTrip) {
  for (const ClosureSelectionInfo& info : kClosureSelections) {
    EXPECT_EQ(to_string(info.value), info.name);
    EXPECT_EQ(parse_closure_selection(info.name), info.value);
  }
  EXPECT_FALSE(parse_closure_selection("pcm").has_value());
  EXPECT_EQ(ClosingSettings{}.selection, ClosureSelection::iterative_chi2);  // the default
}

TEST(CloseLoops, PcmCliquePassesTheSameJointCheckUnlessSwitchedOff) {
  // With a threshold no closure can pass, the check distrusts every closure of the clique in
  // turn; PCM as published (no check) trusts the clique as it is, with one solve.
  const slam::FragmentSet set = two_laps();
  const std::vector<slam::Pose2> start = slam::chain(slam::mean_alignments(set));
  ClosingSettings strict;
  strict.outlier_chi2 = 1e-12;
  for (const ClosureSelection selection :
       {ClosureSelection::pcm_exact, ClosureSelection::pcm_aco}) {
    strict.selection = selection;
    strict.pcm.check_clique = true;
    const Closing checked = close_loops(set, start, strict);
    ASSERT_TRUE(checked.clique);
    EXPECT_EQ(checked.clique->clique.vertices.size(), set.closures.size());
    EXPECT_EQ(std::count(checked.trusted.begin(), checked.trusted.end(), true), 0);
    EXPECT_EQ(checked.solves, set.closures.size());
    strict.pcm.check_clique = false;
    const Closing published = close_loops(set, start, strict);
    EXPECT_EQ(std::count(published.trusted.begin(), published.trusted.end(), true),
              static_cast<std::ptrdiff_t>(set.closures.size()));
    EXPECT_EQ(published.solves, 1U);
  }
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
