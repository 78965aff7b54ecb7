// Exhaustive search and random sampling; the hybrid against the proven optimum.

#include <gtest/gtest.h>

#include <limits>

#include "antslam/aco/variants.hpp"
#include "antslam/slamgraph/search_baselines.hpp"
#include "antslam/slamgraph/slam_problem.hpp"
#include "support.hpp"

namespace antslam::slam {
namespace {

/// Plain enumeration of every path, no pruning.
SearchResult enumerate_all(const FragmentSet& set) {
  const std::size_t layers = set.layer_count();
  std::vector<std::uint32_t> choice(layers, 0);
  SearchResult best;
  best.weight = std::numeric_limits<double>::infinity();
  for (;;) {
    const double w = path_weight(set, choice);
    if (w < best.weight) best = {choice, w, 0};
    std::size_t l = 0;
    while (l < layers && ++choice[l] == set.fragments[l + 1].samples.size()) choice[l++] = 0;
    if (l == layers) return best;
  }
}

TEST(Exhaustive, FindsTheSameOptimumAsPlainEnumeration) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const FragmentSet set = testing::random_set(5, 4 + seed % 3, 1 + seed % 3, seed);
    const SearchResult expected = enumerate_all(set);
    const SearchResult found = exhaustive_search(set, 1'000'000);
    EXPECT_EQ(found.choice, expected.choice) << "seed " << seed;
    EXPECT_NEAR(found.weight, expected.weight, 1e-12);
    EXPECT_NEAR(found.weight, path_weight(set, found.choice), 1e-12);
    EXPECT_LE(found.evaluations, path_count(set));  // branch and bound cuts paths
  }
}

TEST(Exhaustive, RefusesTooLargeTrees) {
  const FragmentSet set = testing::random_set(9, 20, 1, 1);
  EXPECT_EQ(path_count(set), 25'600'000'000ULL);
  try {
    exhaustive_search(set, 1'000'000);
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "exhaustive search over 25600000000 paths exceeds the limit of 1000000");
  }
}

// On small sets (N = 5, M = 6) the hybrid with the paper's parameters finds the
// exhaustive optimum for most seeds.
TEST(Exhaustive, HybridFindsTheOptimumOnSmallSetsForMostSeeds) {
  int found = 0, runs = 0;
  for (std::uint64_t set_seed = 1; set_seed <= 4; ++set_seed) {
    const FragmentSet set = testing::random_set(5, 6, 2, set_seed);
    const double optimum = exhaustive_search(set, 1'000'000).weight;
    const SlamProblem problem(set);
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      aco::Parameters p;
      p.variant = aco::Variant::hybrid;
      p.seed = seed;
      const aco::RunResult r =
          aco::solve(problem, p, {.max_iterations = 300}, aco::SerialBackend{});
      ++runs;
      found += r.best.cost <= optimum + 1e-12 ? 1 : 0;
      EXPECT_GE(r.best.cost, optimum - 1e-12);  // nothing beats the proven optimum
    }
  }
  EXPECT_GE(found, runs * 8 / 10) << found << " of " << runs;
}

TEST(RandomSearch, UsesTheBudgetAndIsReproducible) {
  const FragmentSet set = testing::random_set(6, 5, 2, 2);
  const SlamProblem problem(set);
  std::uint64_t last_round = 0;
  const SearchResult a =
      random_search(problem, 50, 20, 7, 0.0, [&](std::uint64_t round, std::uint64_t, double) {
        EXPECT_GT(round, last_round);
        last_round = round;
      });
  const SearchResult b = random_search(problem, 50, 20, 7, 0.0);
  EXPECT_EQ(a.evaluations, 1000U);
  EXPECT_EQ(a.choice, b.choice);
  EXPECT_NEAR(a.weight, problem.cost(a.choice), 0.0);
  EXPECT_GE(a.weight, exhaustive_search(set, 1'000'000).weight - 1e-12);
}

}  // namespace
}  // namespace antslam::slam
