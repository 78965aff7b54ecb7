// The continuous eq. (10) objective and its analytic gradient.

#include <gtest/gtest.h>

#include <cmath>

#include "antslam/slamgraph/alignment_objective.hpp"
#include "support.hpp"

namespace antslam::slam {
namespace {

TEST(AlignmentObjective, EqualsTheWeightOfTheChosenSamples) {
  for (std::size_t closures : {1U, 4U}) {
    const FragmentSet set = testing::random_set(8, 4, closures, 3);
    AlignmentObjective objective(set);
    aco::Rng rng(5);
    for (int t = 0; t < 20; ++t) {
      std::vector<std::uint32_t> choice(7);
      for (auto& c : choice) c = rng.below(4);
      const auto x = AlignmentObjective::pack(chosen_alignments(set, choice));
      const Scores s = objective.evaluate(x);
      EXPECT_NEAR(s.weight, path_weight(set, choice), 1e-12);
      const Scores reference = score(set, chosen_alignments(set, choice));
      EXPECT_NEAR(s.chi2, reference.chi2, 1e-9 * (1.0 + reference.chi2));
    }
  }
}

// Central differences on random sets with several closures, random points (angles outside
// [-pi, pi) included: the wrap must not matter).
// Also at kernel widths other than 1 (graduated refinement).
TEST(AlignmentObjective, GradientMatchesFiniteDifferences) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const FragmentSet set = testing::random_set(7, 3, 1 + seed, seed, 0.8);
    AlignmentObjective objective(set);
    objective.set_kernel_width(seed % 2 == 0 ? 1.0 : 2.5 * static_cast<double>(seed));
    aco::Rng rng(seed);
    std::vector<double> x;
    for (std::size_t i = 1; i < set.fragments.size(); ++i) {
      const Pose2 p = set.fragments[i].samples[rng.below(3)];
      x.insert(x.end(), {p.x, p.y, p.theta + (i % 2 == 0 ? 2.0 * std::numbers::pi : 0.0)});
    }
    std::vector<double> gradient(x.size());
    objective.evaluate(x, gradient);
    const double h = 1e-6;
    for (std::size_t k = 0; k < x.size(); ++k) {
      std::vector<double> plus = x, minus = x;
      plus[k] += h;
      minus[k] -= h;
      const double numeric =
          (objective.evaluate(plus).weight - objective.evaluate(minus).weight) / (2.0 * h);
      ASSERT_NEAR(gradient[k], numeric, 1e-6 * (1.0 + std::abs(numeric)))
          << "seed " << seed << " coordinate " << k;
    }
  }
}

/// One alignment with mu = (0, 0, 0) and one closure on the same pair with anchor = identity and
/// H = (2, 0, 0), unit covariances.
FragmentSet one_alignment_one_closure() {
  FragmentSet set;
  set.fragments.resize(2);
  set.fragments[1].alignment = Gaussian2(Pose2{}, Eigen::Matrix3d::Identity());
  set.fragments[1].samples = {Pose2{}};
  set.closures = {{0, 1, Pose2{}, Gaussian2(Pose2{2.0, 0.0, 0.0}, Eigen::Matrix3d::Identity())}};
  return set;
}

// Hand-computed: one alignment, one closure on the same pair with anchor = identity, unit
// covariances. At X = (1, 0, 0) with mu = (0, 0, 0) and H = (2, 0, 0): m_align = 1,
// m_closure = 1, W = 2 (1 - e^-0.5), dW/dx = e^-0.5 * (1) + e^-0.5 * (-1) = 0.
TEST(AlignmentObjective, HandComputedValueAndGradient) {
  AlignmentObjective objective(one_alignment_one_closure());
  std::vector<double> g(3);
  const Scores s = objective.evaluate(std::vector<double>{1.0, 0.0, 0.0}, g);
  EXPECT_NEAR(s.weight, 2.0 * (1.0 - std::exp(-0.5)), 1e-15);
  EXPECT_NEAR(s.chi2, 2.0, 1e-15);
  EXPECT_NEAR(g[0], 0.0, 1e-15);
  EXPECT_NEAR(g[1], 0.0, 1e-15);
  EXPECT_NEAR(g[2], 0.0, 1e-15);
  objective.evaluate(std::vector<double>{0.5, 0.0, 0.0}, g);  // pulled towards H = 2
  EXPECT_NEAR(g[0], std::exp(-0.125) * 0.5 - std::exp(-1.125) * 1.5, 1e-15);
}

// The same set at kernel width s = 2: each term is s^2 (1 - exp(-m / (2 s^2))) and its gradient
// exp(-m / (2 s^2)) Omega r. At X = (0.5, 0, 0): m_align = 0.25, m_closure = 2.25.
TEST(AlignmentObjective, HandComputedWidenedValueAndGradient) {
  AlignmentObjective objective(one_alignment_one_closure());
  objective.set_kernel_width(2.0);
  std::vector<double> g(3);
  const Scores s = objective.evaluate(std::vector<double>{0.5, 0.0, 0.0}, g);
  EXPECT_NEAR(s.weight, 4.0 * (2.0 - std::exp(-0.25 / 8.0) - std::exp(-2.25 / 8.0)), 1e-15);
  EXPECT_NEAR(s.chi2, 2.5, 1e-15);
  EXPECT_NEAR(g[0], std::exp(-0.25 / 8.0) * 0.5 - std::exp(-2.25 / 8.0) * 1.5, 1e-15);
  // A very wide kernel is least squares: the sum tends to chi2 / 2.
  objective.set_kernel_width(1e4);
  EXPECT_NEAR(objective.evaluate(std::vector<double>{0.5, 0.0, 0.0}).weight, 1.25, 1e-6);
  EXPECT_THROW(objective.set_kernel_width(0.0), std::invalid_argument);
  EXPECT_THROW(objective.set_kernel_width(std::nan("")), std::invalid_argument);
}

TEST(AlignmentObjective, PackAndUnpackRoundTrip) {
  const std::vector<Pose2> poses{{1.0, 2.0, 0.5}, {-3.0, 0.25, -2.0}};
  const auto back = AlignmentObjective::unpack(AlignmentObjective::pack(poses));
  ASSERT_EQ(back.size(), 2U);
  EXPECT_EQ(back[1].x, -3.0);
  EXPECT_EQ(back[1].theta, -2.0);
  EXPECT_THROW(AlignmentObjective::unpack(std::vector<double>{1.0, 2.0}), std::invalid_argument);
}

TEST(AlignmentObjective, RejectsWrongSizes) {
  const FragmentSet set = testing::random_set(4, 2, 1, 1);
  AlignmentObjective objective(set);
  EXPECT_THROW(objective.evaluate(std::vector<double>(8)), std::invalid_argument);
  std::vector<double> g(3);
  EXPECT_THROW(objective.evaluate(std::vector<double>(9), g), std::invalid_argument);
}

}  // namespace
}  // namespace antslam::slam
