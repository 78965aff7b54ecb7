// NLopt refinement: never worse than its start, inside its box, and it does reach the optimum.

#include <gtest/gtest.h>

#include <cmath>

#include "antslam/slamgraph/refine.hpp"
#include "antslam/slamgraph/synth.hpp"
#include "support.hpp"

namespace antslam::slam {
namespace {

TEST(Refine, NeverWorseAndInsideTheBox) {
  for (RefineAlgorithm algorithm :
       {RefineAlgorithm::lbfgs, RefineAlgorithm::slsqp, RefineAlgorithm::bobyqa}) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      const FragmentSet set = testing::random_set(6, 4, 1 + seed % 3, seed, 0.5);
      Refiner refiner(set, {.algorithm = algorithm, .max_evaluations = 300});
      aco::Rng rng(seed);
      for (int t = 0; t < 5; ++t) {
        std::vector<std::uint32_t> choice(5);
        for (auto& c : choice) c = rng.below(4);
        const RefineResult r = refiner.refine(chosen_alignments(set, choice));
        EXPECT_NEAR(r.start.weight, path_weight(set, choice), 1e-12);
        EXPECT_LE(r.scores.weight, r.start.weight) << to_string(algorithm);
        EXPECT_NEAR(r.scores.weight, score(set, r.alignments).weight, 1e-9);
        const auto x = AlignmentObjective::pack(r.alignments);
        for (std::size_t k = 0; k < x.size(); ++k) {
          if (k % 3 == 2) continue;  // angles are re-wrapped on output
          EXPECT_GE(x[k], refiner.lower()[k] - 1e-12);
          EXPECT_LE(x[k], refiner.upper()[k] + 1e-12);
        }
      }
    }
  }
}

// A spent budget: NLopt stops at its first evaluation past it and no graduated stage starts, so
// the refinement ends after a few evaluations instead of its maximum (optimize() passes what is
// left of --time-limit; the refinement of a 10,000-pose graph once ran on a minute past it).
// Counted, not timed: one evaluation of 300 fragments takes far longer than the microsecond
// left: the scores of the start and of the result, the plain stage's first evaluation and its
// last look at the point; no graduated stage starts.
TEST(Refine, ASpentBudgetStopsAtTheFirstEvaluation) {
  const FragmentSet set = testing::random_set(300, 4, 20, 7, 0.5);
  const std::vector<std::uint32_t> choice(set.layer_count(), 0);
  Refiner refiner(set, {.max_evaluations = 2000});
  const RefineResult spent = refiner.refine(chosen_alignments(set, choice), 1e-6);
  EXPECT_LE(spent.evaluations, 4);
  EXPECT_LE(spent.scores.weight, spent.start.weight);
  const RefineResult unlimited = refiner.refine(chosen_alignments(set, choice));
  EXPECT_GT(unlimited.evaluations, 40);
}

// A noise-free synthetic set has its continuous optimum W = 0 at the ground truth, inside the
// box; from half a sigma off, every algorithm must get there.
TEST(Refine, ReachesTheOptimumOfANoiseFreeSet) {
  SynthSettings s = synth_preset("paper9");
  s.noise_free = true;
  const FragmentSet set = synthesize(s);
  const std::vector<Pose2> truth = relative_alignments(set.reference);
  std::vector<Pose2> start = truth;
  for (std::size_t i = 0; i < start.size(); ++i) {
    const double sign = i % 2 == 0 ? 1.0 : -1.0;
    start[i].x += 0.5 * sign * s.sigma_xy;
    start[i].theta += 0.5 * sign * s.sigma_theta;
  }
  for (RefineAlgorithm algorithm :
       {RefineAlgorithm::lbfgs, RefineAlgorithm::slsqp, RefineAlgorithm::bobyqa}) {
    Refiner refiner(set, {.algorithm = algorithm, .max_evaluations = 5000});
    const RefineResult r = refiner.refine(start);
    EXPECT_GT(r.start.weight, 0.5);
    EXPECT_LT(r.scores.weight, 1e-6) << to_string(algorithm);
    for (std::size_t i = 0; i < truth.size(); ++i) EXPECT_NEAR(r.alignments[i].x, truth[i].x, 1e-3);
  }
}

// A loop whose closure the start misses by more than 20 sigma_H: the closure term of eq. (10) is
// flat there, so the plain refinement cannot move, while graduated non-convexity closes the loop
// (every alignment mean carries the same small heading bias, 0.3 sigma, the closure is exact).
TEST(Refine, GraduatedRefinementClosesALoopThePlainOneCannotSee) {
  SynthSettings s = synth_preset("paper9");
  s.noise_free = true;
  s.closure_sigma_xy = 0.01;
  s.closure_sigma_theta = 0.002;
  FragmentSet set = synthesize(s);
  for (std::size_t i = 1; i < set.fragments.size(); ++i) {
    const Gaussian2& g = *set.fragments[i].alignment;
    Pose2 biased = g.mean();
    biased.theta += 0.3 * s.sigma_theta;
    set.fragments[i].alignment = Gaussian2(biased, g.covariance());
  }
  const LoopClosure& closure = set.closures[0];
  const auto mahalanobis = [&](const std::vector<Pose2>& alignments) {
    const Eigen::Vector3d r = closure.hypothesis.residual(closure_pose(closure, chain(alignments)));
    return std::sqrt(r.dot(closure.hypothesis.information() * r));
  };
  const std::vector<Pose2> means = mean_alignments(set);
  ASSERT_GT(mahalanobis(means), 20.0);

  const RefineResult plain = Refiner(set, {.graduated = false}).refine(means);
  EXPECT_NEAR(plain.scores.weight, 1.0, 1e-9);  // only the (saturated) closure term
  EXPECT_FALSE(plain.graduated);

  const RefineResult graduated = Refiner(set, {}).refine(means);
  EXPECT_TRUE(graduated.graduated);
  EXPECT_LT(graduated.scores.weight, 0.5);
  EXPECT_LT(mahalanobis(graduated.alignments), 1.0);
  const std::vector<Pose2> frames = chain(graduated.alignments);
  for (std::size_t i = 0; i < frames.size(); ++i)
    EXPECT_LT((frames[i].translation() - set.reference[i].translation()).norm(), 0.01) << i;
}

// The graduated result replaces the plain one only when its eq. (10) weight is lower, so the
// refinement with it is never worse than without it.
TEST(Refine, GraduatedIsNeverWorseThanPlain) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const FragmentSet set = testing::random_set(7, 4, 1 + seed % 4, seed, 0.5);
    const std::vector<Pose2> means = mean_alignments(set);
    const RefineResult plain = Refiner(set, {.graduated = false}).refine(means);
    const RefineResult both = Refiner(set, {}).refine(means);
    EXPECT_LE(both.scores.weight, plain.scores.weight + 1e-12) << seed;
    EXPECT_NEAR(both.scores.weight, score(set, both.alignments).weight, 1e-9);
  }
}

TEST(Refine, StartOutsideTheBoxWidensIt) {
  const FragmentSet set = testing::random_set(4, 3, 1, 3);
  Refiner refiner(set, {});
  std::vector<Pose2> start = mean_alignments(set);
  start[1].x = refiner.upper()[3] + 50.0;
  const RefineResult r = refiner.refine(start);
  EXPECT_LE(r.scores.weight, r.start.weight);
}

TEST(Refine, ValidatesItsInput) {
  const FragmentSet set = testing::random_set(4, 3, 1, 3);
  EXPECT_THROW(Refiner(set, {.bound_sigmas = -1.0}), std::invalid_argument);
  EXPECT_THROW(Refiner(set, {.max_evaluations = 0}), std::invalid_argument);
  EXPECT_THROW(Refiner(set, {.graduation_factor = 1.0}), std::invalid_argument);
  Refiner refiner(set, {});
  EXPECT_THROW(refiner.refine(std::vector<Pose2>(2)), std::invalid_argument);
  EXPECT_EQ(parse_refine_algorithm("slsqp"), RefineAlgorithm::slsqp);
  EXPECT_THROW(parse_refine_algorithm("newton"), std::invalid_argument);
}

}  // namespace
}  // namespace antslam::slam
