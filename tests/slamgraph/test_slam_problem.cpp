// The engine's AntSLAM problem (fast eq. 10) against independent recomputations.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <Eigen/LU>

#include "antslam/aco/problem.hpp"
#include "antslam/slamgraph/slam_problem.hpp"
#include "support.hpp"

namespace antslam::slam {
namespace {

static_assert(aco::LayeredProblem<SlamProblem>);

/// Eq. (8) and (10) written out from scratch with trigonometry on every step: no Pose2
/// operators, no Gaussian2::value, full information matrices.
double brute_force_weight(const FragmentSet& set, std::span<const std::uint32_t> choice) {
  const std::size_t n = set.fragments.size();
  std::vector<Eigen::Vector3d> world(n, Eigen::Vector3d::Zero());
  double weight = 0.0;
  const auto term = [](const Gaussian2& g, Eigen::Vector3d r) {
    r.z() = std::remainder(r.z(), 2.0 * std::numbers::pi);
    return 1.0 - std::exp(-0.5 * r.dot(g.covariance().inverse() * r));
  };
  for (std::size_t i = 1; i < n; ++i) {
    const Pose2& s = set.fragments[i].samples[choice[i - 1]];
    const Eigen::Vector3d& p = world[i - 1];
    world[i] = {p.x() + std::cos(p.z()) * s.x - std::sin(p.z()) * s.y,
                p.y() + std::sin(p.z()) * s.x + std::cos(p.z()) * s.y, p.z() + s.theta};
    weight +=
        term(*set.fragments[i].alignment, s.vector() - set.fragments[i].alignment->mean().vector());
  }
  for (const LoopClosure& c : set.closures) {
    const Eigen::Vector3d& a = world[c.from];
    const Eigen::Vector3d& b = world[c.to];
    const Eigen::Vector2d g(b.x() + std::cos(b.z()) * c.anchor.x - std::sin(b.z()) * c.anchor.y,
                            b.y() + std::sin(b.z()) * c.anchor.x + std::cos(b.z()) * c.anchor.y);
    const Eigen::Vector2d d = g - a.head<2>();
    const Eigen::Vector3d local(std::cos(a.z()) * d.x() + std::sin(a.z()) * d.y(),
                                -std::sin(a.z()) * d.x() + std::cos(a.z()) * d.y(),
                                b.z() + c.anchor.theta - a.z());
    weight += term(c.hypothesis, local - c.hypothesis.mean().vector());
  }
  return weight;
}

TEST(SlamProblem, ShapeFollowsTheSet) {
  const FragmentSet set = testing::random_set(6, 4, 1, 1);
  const SlamProblem problem(set);
  EXPECT_EQ(problem.layer_count(), 5U);
  for (std::size_t l = 0; l < 5; ++l) EXPECT_EQ(problem.option_count(l), 4U);
}

// Single loop (the paper) and several loops (ours), including more closures than the stack
// buffer of kept frames holds.
TEST(SlamProblem, CostMatchesBruteForceWithOneAndSeveralLoops) {
  for (std::size_t closures : {1U, 3U, 8U, 40U}) {
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      const FragmentSet set = testing::random_set(9, 5, closures, seed);
      const SlamProblem problem(set);
      aco::Rng rng(seed);
      for (int trial = 0; trial < 50; ++trial) {
        std::vector<std::uint32_t> choice(8);
        for (auto& c : choice) c = rng.below(5);
        const double expected = brute_force_weight(set, choice);
        ASSERT_NEAR(problem.cost(choice), expected, 1e-9) << closures << " closures";
        ASSERT_NEAR(path_weight(set, choice), expected, 1e-9);
      }
    }
  }
}

TEST(SlamProblem, SeveralLoopsAddTheirTerms) {
  FragmentSet one = testing::random_set(7, 3, 1, 9);
  FragmentSet three = testing::random_set(7, 3, 3, 9);
  three.closures[0] = one.closures[0];
  const std::vector<std::uint32_t> choice{0, 1, 2, 0, 1, 2};
  const auto frames = world_frames(three, choice);
  double extra = 0.0;
  for (std::size_t c = 1; c < 3; ++c)
    extra += 1.0 - three.closures[c].hypothesis.value(closure_pose(three.closures[c], frames));
  EXPECT_GT(extra, 0.0);
  // Same alignments and samples (same seed), so only the extra closures differ.
  EXPECT_NEAR(SlamProblem(three).cost(choice), SlamProblem(one).cost(choice) + extra, 1e-12);
}

TEST(SlamProblem, EveryTermIsInTheUnitInterval) {
  const FragmentSet set = testing::random_set(5, 3, 2, 4);
  const SlamProblem problem(set);
  for (std::uint32_t a = 0; a < 3; ++a)
    for (std::uint32_t b = 0; b < 3; ++b) {
      const std::vector<std::uint32_t> choice{a, b, 0, 1};
      const double w = problem.cost(choice);
      EXPECT_GE(w, 0.0);
      EXPECT_LE(w, 4.0 + 2.0);  // 4 alignment terms + 2 closure terms, each <= 1
    }
}

TEST(SlamProblem, RejectsAnInvalidSet) {
  FragmentSet set = testing::random_set(4, 2, 1, 1);
  set.closures[0].from = 3;
  EXPECT_THROW(SlamProblem{set}, std::invalid_argument);
}

}  // namespace
}  // namespace antslam::slam
