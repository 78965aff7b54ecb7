// The Ceres baselines: ground truth of a noise-free set, the closed-form optimum with correlated
// covariances (which catches whitening by the wrong Cholesky factor), and the costs they report.

#include <gtest/gtest.h>

#include "antslam/slamgraph/ceres_baseline.hpp"
#include "antslam/slamgraph/synth.hpp"
#include "support.hpp"

namespace antslam::slam {
namespace {

TEST(Ceres, RecoversTheGroundTruthOfANoiseFreeSet) {
  SynthSettings s = synth_preset("paper15");
  s.noise_free = true;
  s.correlation = 0.4;
  const FragmentSet set = synthesize(s);
  std::vector<Pose2> start(set.layer_count());
  for (std::size_t i = 0; i < start.size(); ++i) start[i] = set.fragments[i + 1].samples[0];
  for (bool robust : {false, true}) {
    const CeresResult r = optimize_with_ceres(set, start, robust, {});
    ASSERT_EQ(r.frames.size(), set.reference.size());
    for (std::size_t i = 0; i < r.frames.size(); ++i) {
      EXPECT_NEAR(r.frames[i].x, set.reference[i].x, 1e-6) << "robust " << robust;
      EXPECT_NEAR(r.frames[i].y, set.reference[i].y, 1e-6);
      EXPECT_NEAR(wrap_angle(r.frames[i].theta - set.reference[i].theta), 0.0, 1e-7);
    }
    EXPECT_LT(r.final_cost, 1e-10);
  }
}

Eigen::Matrix3d correlated(double a, double b) {
  Eigen::Matrix3d c;
  c << 0.04, a, 0.002, a, 0.09, b, 0.002, b, 0.01;
  return c;
}

// One alignment and one closure on the same pair (anchor = identity, F_1 = W): both residuals
// are X - m, so the least-squares optimum is X* = (O1 + O2)^-1 (O1 m1 + O2 m2). Whitening with
// the lower Cholesky factor L of Omega would minimise r^T L^T L r instead and miss X*.
TEST(Ceres, MatchesTheClosedFormOptimumWithCorrelatedCovariances) {
  const Gaussian2 g1(Pose2{1.0, 0.5, 0.1}, correlated(0.03, -0.006));
  const Gaussian2 g2(Pose2{1.3, 0.2, -0.05}, correlated(-0.05, 0.008));
  FragmentSet set;
  set.fragments.resize(2);
  set.fragments[1].alignment = g1;
  set.fragments[1].samples = {g1.mean()};
  set.closures = {{0, 1, Pose2{}, g2}};
  const Eigen::Matrix3d o1 = g1.information(), o2 = g2.information();
  const Eigen::Vector3d expected =
      (o1 + o2).ldlt().solve(o1 * g1.mean().vector() + o2 * g2.mean().vector());
  const CeresResult r = optimize_with_ceres(set, std::vector<Pose2>{Pose2{}}, false, {});
  EXPECT_NEAR(r.frames[1].x, expected.x(), 1e-6);
  EXPECT_NEAR(r.frames[1].y, expected.y(), 1e-6);
  EXPECT_NEAR(r.frames[1].theta, expected.z(), 1e-6);
  // The wrong factor gives a measurably different optimum, so the check above can fail.
  const Eigen::Matrix3d l1 = o1.llt().matrixL(), l2 = o2.llt().matrixL();
  const Eigen::Matrix3d w1 = l1.transpose() * l1, w2 = l2.transpose() * l2;
  const Eigen::Vector3d wrong =
      (w1 + w2).ldlt().solve(w1 * g1.mean().vector() + w2 * g2.mean().vector());
  EXPECT_GT((wrong - expected).norm(), 1e-3);
}

// Ceres' own cost is chi2 / 2 (plain) and the eq. (10) weight (robust), computed independently
// with the full information matrices on sets with correlated covariances.
TEST(Ceres, ReportedCostsAreChi2AndTheWeight) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const FragmentSet set = testing::random_set(6, 2, 3, seed);
    const std::vector<Pose2> start = mean_alignments(set);
    for (bool robust : {false, true}) {
      const CeresResult r = optimize_with_ceres(set, start, robust, {.max_iterations = 3});
      const Scores s = score(set, relative_alignments(r.frames));
      EXPECT_NEAR(r.final_cost, robust ? s.weight : 0.5 * s.chi2, 1e-9 * (1.0 + s.chi2));
    }
  }
}

TEST(Ceres, PlainLeastSquaresLowersChi2) {
  const FragmentSet set = testing::random_set(8, 2, 4, 5);
  const std::vector<Pose2> start = mean_alignments(set);
  const CeresResult r = optimize_with_ceres(set, start, false, {});
  EXPECT_LT(score(set, relative_alignments(r.frames)).chi2, score(set, start).chi2);
  EXPECT_TRUE(r.converged);
  EXPECT_THROW(optimize_with_ceres(set, std::vector<Pose2>(3), false, {}), std::invalid_argument);
}

}  // namespace
}  // namespace antslam::slam
