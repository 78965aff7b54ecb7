// The assignment family (MMAS-QAP's construction): ants build permutations, follow a trail that
// allows one place per item, draw only from their own stream, and deposit on (item, place) pairs.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <span>
#include <vector>

#include "antslam/aco/assignment_family.hpp"
#include "antslam/aco/colony.hpp"
#include "antslam/aco/rules.hpp"
#include "antslam/aco/update_mmas.hpp"

namespace antslam::aco {
namespace {

/// Item i wants place target[i]; the cost is the number of items elsewhere.
struct Placement {
  std::vector<std::uint32_t> target;
  std::size_t size() const { return target.size(); }
  double cost(std::span<const std::uint32_t> p) const {
    double wrong = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) wrong += p[i] != target[i] ? 1.0 : 0.0;
    return wrong;
  }
};

/// The same with a heuristic that prefers place n - 1 - i for item i.
struct PlacementWithHeuristic : Placement {
  double heuristic(std::uint32_t i, std::uint32_t l) const {
    return l + i + 1 == size() ? 2.0 : 1.0;
  }
};

}  // namespace

template <>
struct family_of<Placement> {
  using type = AssignmentFamily<Placement>;
};

namespace {

static_assert(FamilyOfProblem<Placement>);
static_assert(AssignmentProblemWithHeuristic<PlacementWithHeuristic>);

/// Whether p is a permutation of 0..n-1.
bool is_permutation(std::span<const std::uint32_t> p) {
  std::vector<std::uint32_t> identity(p.size());
  std::iota(identity.begin(), identity.end(), 0U);
  return std::is_permutation(p.begin(), p.end(), identity.begin(), identity.end());
}

TEST(AssignmentFamily, AntsBuildPermutations) {
  const Placement problem{{3, 1, 4, 0, 2, 6, 5}};
  AssignmentFamily<Placement> family(problem, 1.0, 2.0);
  family.reserve_ants(2);
  family.trail().fill(1.0);
  family.trail().deposit(problem.target, 3.0);  // not every choice is uniform
  family.prepare(RandomProportional{});
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    Rng rng(seed);
    std::vector<std::uint32_t> path;
    family.construct(seed % 2, path, rng, RandomProportional{});
    ASSERT_TRUE(is_permutation(path)) << "seed " << seed;
  }
}

TEST(AssignmentFamily, FollowsATrailThatAllowsOnePlacePerItem) {
  const Placement problem{{3, 1, 4, 0, 2, 6, 5}};
  AssignmentFamily<Placement> family(problem, 2.0, 1.0);
  family.reserve_ants(1);
  family.trail().fill(0.0);
  family.trail().deposit(problem.target, 1.0);
  family.prepare(RandomProportional{});
  for (std::uint64_t seed = 0; seed < 50; ++seed) {
    Rng rng(seed);
    std::vector<std::uint32_t> path;
    family.construct(0, path, rng, RandomProportional{});
    ASSERT_EQ(path, problem.target) << "seed " << seed;
  }
}

TEST(AssignmentFamily, AnAntDependsOnItsStreamOnly) {
  const Placement problem{{0, 1, 2, 3, 4, 5, 6, 7}};
  AssignmentFamily<Placement> family(problem, 1.0, 2.0);
  family.reserve_ants(3);
  family.trail().fill(1.0);
  family.prepare(RandomProportional{});
  std::vector<std::uint32_t> first;
  std::vector<std::uint32_t> second;
  Rng a(7);
  family.construct(0, first, a, RandomProportional{});
  Rng b(7);
  family.construct(2, second, b, RandomProportional{});
  EXPECT_EQ(first, second);
}

TEST(AssignmentTrail, DepositsOnTheItemPlacePairs) {
  AssignmentTrail trail(3);
  trail.fill(1.0);
  const std::vector<std::uint32_t> path{2, 0, 1};
  trail.deposit(path, 0.5);
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t l = 0; l < 3; ++l)
      EXPECT_EQ(trail.at(i, l), l == path[i] ? 1.5 : 1.0) << i << ", " << l;
  EXPECT_EQ(trail.branching_factor(0.05), 1.0);  // one strong place per item
  EXPECT_EQ(trail.decision_count(), 3U);
  EXPECT_EQ(trail.mean_options(), 2.0);
}

TEST(AssignmentFamily, ReferenceCostIsTheGreedyAssignment) {
  const Placement problem{{1, 0, 2, 3}};
  EXPECT_EQ(AssignmentFamily<Placement>(problem, 1.0, 2.0).reference_cost(), 2.0);  // identity
  // Greedy on the heuristic: (3, 2, 1, 0), two items misplaced.
  const PlacementWithHeuristic reversed{{{3, 2, 0, 1}}};
  EXPECT_EQ(AssignmentFamily<PlacementWithHeuristic>(reversed, 1.0, 2.0).reference_cost(), 2.0);
}

TEST(AssignmentFamily, AColonyFindsTheTargetPermutation) {
  const Placement problem{{5, 3, 0, 7, 1, 6, 2, 4}};
  Colony<Placement, RandomProportional, MaxMinUpdate> colony(problem, {.ants = 10, .seed = 2}, {},
                                                             MaxMinUpdate());
  const RunResult r = colony.run({.max_iterations = 1000, .target_cost = 0.0});
  EXPECT_EQ(r.best.path, problem.target);
}

}  // namespace
}  // namespace antslam::aco
