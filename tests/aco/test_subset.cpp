// The subset-selection family: its trail, its construction (maximal compatible sets, the greedy
// reference), and every variant on a small problem that is not a clique problem.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "antslam/aco/rules.hpp"
#include "antslam/aco/subset_family.hpp"
#include "antslam/aco/subset_trail.hpp"
#include "antslam/aco/variants.hpp"
#include "test_problems.hpp"

namespace antslam::aco {
namespace {

TEST(SubsetTrail, EvaporatesDepositsAndClamps) {
  SubsetTrail trail(4);
  trail.fill(2.0);
  trail.evaporate(0.25);
  const std::vector<std::uint32_t> set{1, 3};
  trail.deposit(set, 0.5);
  EXPECT_EQ(trail.at(0), 1.5);
  EXPECT_EQ(trail.at(1), 2.0);
  EXPECT_EQ(trail.at(3), 2.0);
  trail.clamp(1.6, 1.9);
  EXPECT_EQ(trail.min_value(), 1.6);
  EXPECT_EQ(trail.max_value(), 1.9);
  EXPECT_EQ(trail.decision_count(), 4U);
  EXPECT_THROW(SubsetTrail(0), std::invalid_argument);
}

TEST(SubsetTrail, BranchingFactorCountsUndecidedElements) {
  SubsetTrail trail(5);
  trail.fill(1.0);
  const std::vector<std::uint32_t> taken{0}, middle{2}, near_top{3};
  trail.deposit(taken, 9.0);     // 10: decided in
  trail.deposit(middle, 4.5);    // 5.5: undecided
  trail.deposit(near_top, 8.2);  // 9.2: within 0.1 x 9 of the top: decided in
  // Elements 1 and 4 sit at the minimum: decided out. One undecided of five.
  EXPECT_DOUBLE_EQ(trail.branching_factor(0.1), 1.2);
  EXPECT_DOUBLE_EQ(trail.branching_factor(0.6), 1.0);  // the cuts cross: nothing undecided
}

TEST(SubsetFamily, AntsBuildMaximalCompatibleSets) {
  const testing::ConflictSubsetProblem problem(30, 0.2, 4);
  SubsetFamily<testing::ConflictSubsetProblem> family(problem, 1.0, 2.0);
  family.trail().fill(1.0);
  family.reserve_ants(1);
  family.prepare(RandomProportional{});
  std::vector<std::uint32_t> set;
  for (std::uint64_t a = 0; a < 50; ++a) {
    Rng rng = ant_stream(7, 1, a);
    family.construct(0, set, rng, RandomProportional{});
    EXPECT_TRUE(problem.maximal_independent(set));
  }
}

/// The random-proportional rule that checks, at every step, that the sum the construction hands
/// it is exactly what detail::sum gives for the candidates' weights.
struct SumCheckingRule {
  template <class R>
  std::size_t choose(std::span<const double> w, double total, R& rng) const {
    EXPECT_EQ(total, detail::sum(w));
    ++*steps;
    return RandomProportional{}.choose(w, total, rng);
  }
  std::size_t* steps;
};

TEST(SubsetFamily, TheSumOfTheCandidatesWeightsIsKeptExactly) {
  const testing::ConflictSubsetProblem problem(40, 0.3, 5);
  SubsetFamily<testing::ConflictSubsetProblem> family(problem, 1.0, 2.0);
  family.trail().fill(1.0);
  family.reserve_ants(1);
  std::size_t steps = 0;
  const SumCheckingRule rule{&steps};
  family.prepare(rule);
  std::vector<std::uint32_t> checked, plain;
  for (std::uint64_t a = 0; a < 20; ++a) {
    Rng rng = ant_stream(3, 1, a), same = ant_stream(3, 1, a);
    family.construct(0, checked, rng, rule);
    family.construct(0, plain, same, RandomProportional{});
    EXPECT_EQ(checked, plain);
  }
  EXPECT_GT(steps, 20U);
}

/// Three elements, 0 conflicts with 1; heuristic 3, 2, 1: the greedy takes 0, then 2.
struct TinySubsetProblem {
  std::size_t element_count() const { return 3; }
  bool compatible(std::uint32_t i, std::uint32_t j) const { return i + j != 1; }
  double heuristic(std::uint32_t e) const { return 3.0 - e; }
  double cost(std::span<const std::uint32_t> set) const {
    double c = 10.0;
    for (std::uint32_t e : set) c -= 1.0 + e;
    return c;
  }
};

TEST(SubsetFamily, ReferenceCostIsTheGreedySet) {
  const TinySubsetProblem problem;
  const SubsetFamily<TinySubsetProblem> family(problem, 1.0, 2.0);
  EXPECT_EQ(family.reference_cost(), 10.0 - 1.0 - 3.0);
}

class SubsetVariant : public ::testing::TestWithParam<Variant> {};

TEST_P(SubsetVariant, FindsTheOptimumOfASmallIndependentSetProblem) {
  const testing::ConflictSubsetProblem problem(16, 0.3, 11);
  const double optimum = problem.optimum();
  Parameters p;
  p.variant = GetParam();
  p.seed = 3;
  const RunResult result = solve(problem, p, {.max_iterations = 300, .target_cost = optimum});
  EXPECT_EQ(result.best.cost, optimum);
  EXPECT_TRUE(problem.maximal_independent(result.best.path));
}

INSTANTIATE_TEST_SUITE_P(All, SubsetVariant, ::testing::ValuesIn(all_variants()),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

}  // namespace
}  // namespace antslam::aco
