// NLopt refinement: never worse than its start, inside its box, and it does reach the optimum.

#include <gtest/gtest.h>

#include "slamgraph/refine.hpp"
#include "slamgraph/synth.hpp"
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
  Refiner refiner(set, {});
  EXPECT_THROW(refiner.refine(std::vector<Pose2>(2)), std::invalid_argument);
  EXPECT_EQ(parse_refine_algorithm("slsqp"), RefineAlgorithm::slsqp);
  EXPECT_THROW(parse_refine_algorithm("newton"), std::invalid_argument);
}

}  // namespace
}  // namespace antslam::slam
