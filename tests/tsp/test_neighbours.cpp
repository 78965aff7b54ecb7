// Neighbour lists and the nearest-unvisited search, cross-checked against brute force; the
// construction gives the same tours with the fast fallback as with the engine's scan.

#include <gtest/gtest.h>

#include <algorithm>

#include "antslam/aco/permutation_family.hpp"
#include "antslam/aco/rules.hpp"
#include "antslam/tsp/neighbours.hpp"
#include "antslam/tsp/problem.hpp"
#include "antslam/tsp/tsplib.hpp"
#include "tsp_test_support.hpp"

namespace antslam::tsp {
namespace {

/// Instances with the grid's hard cases: duplicates, clusters, a line, a tiny cell count.
std::vector<Instance> grid_cases() {
  std::vector<Instance> cases;
  for (EdgeWeightType t : {EdgeWeightType::euc_2d, EdgeWeightType::ceil_2d, EdgeWeightType::att})
    cases.push_back(testing::random_instance(400, 11, t));
  aco::Rng rng(3);
  std::vector<Point> clustered;
  for (int i = 0; i < 300; ++i) {
    const double cx = i % 3 == 0 ? 10.0 : 900.0;  // two dense clusters, far apart
    clustered.push_back({cx + std::floor(10.0 * rng.uniform()), std::floor(10.0 * rng.uniform())});
  }
  cases.emplace_back("clusters", EdgeWeightType::euc_2d, clustered);
  std::vector<Point> line;
  for (int i = 0; i < 200; ++i) line.push_back({static_cast<double>(i % 50) * 7.0, 3.0});
  cases.emplace_back("line", EdgeWeightType::euc_2d, line);
  cases.emplace_back("tiny", EdgeWeightType::euc_2d,
                     std::vector<Point>{{0, 0}, {1, 0}, {0, 1}, {1, 1}, {5, 5}});
  return cases;
}

TEST(NeighbourLists, GridSearchEqualsBruteForce) {
  for (const Instance& instance : grid_cases()) {
    SCOPED_TRACE(instance.name());
    const SpatialGrid grid(instance.coords());
    for (std::size_t k : {std::size_t{1}, std::size_t{3}, std::size_t{10}}) {
      const std::size_t kk = std::min(k, instance.size() - 1);
      EXPECT_EQ(nearest_neighbours(instance, kk, &grid),
                nearest_neighbours_brute_force(instance, kk));
    }
  }
}

TEST(NeighbourLists, AreSortedAndExcludeTheCity) {
  const Instance instance = read_instance(testing::fixture("gr17.tsp"));
  const auto lists = nearest_neighbours(instance, 6, nullptr);
  for (std::uint32_t i = 0; i < 17; ++i)
    for (std::size_t r = 0; r < 6; ++r) {
      const std::uint32_t j = lists[i * 6 + r];
      EXPECT_NE(j, i);
      if (r > 0) {
        EXPECT_LE(instance.distance(i, lists[i * 6 + r - 1]), instance.distance(i, j));
      }
    }
  EXPECT_THROW(nearest_neighbours(instance, 17, nullptr), std::invalid_argument);
  EXPECT_THROW(nearest_neighbours(instance, 0, nullptr), std::invalid_argument);
}

/// Removes the cities of random tours from `search`, asking for the nearest unvisited city to
/// a visited one after every `spacing`-th removal, and compares each answer with brute force.
/// Several rounds, so reset() must restore whatever the queries of the last round changed.
void expect_agrees_with_brute_force(const Instance& instance, NearestUnvisited& search,
                                    std::size_t spacing) {
  aco::Rng rng(9);
  for (int round = 0; round < 3; ++round) {
    search.reset();
    std::vector<bool> visited(instance.size(), false);
    const auto order = testing::random_tour(instance.size(), rng);
    for (std::size_t step = 0; step + 1 < order.size(); ++step) {
      search.remove(order[step]);
      visited[order[step]] = true;
      if (step % spacing != 0) continue;
      const std::uint32_t from = order[rng.below(static_cast<std::uint32_t>(step + 1))];
      std::uint32_t expected = 0;
      double best = INFINITY;
      for (std::uint32_t j = 0; j < instance.size(); ++j)
        if (!visited[j] && instance.distance(from, j) < best) {
          best = instance.distance(from, j);
          expected = j;
        }
      ASSERT_EQ(search.nearest(from), expected) << "round " << round << ", step " << step;
    }
    EXPECT_EQ(search.remaining(), 1U);
  }
}

TEST(NearestUnvisited, AgreesWithAScanWhileCitiesAreRemoved) {
  for (const Instance& instance : grid_cases()) {
    SCOPED_TRACE(instance.name());
    const SpatialGrid grid(instance.coords());
    NearestUnvisited search(&instance, &grid);
    expect_agrees_with_brute_force(instance, search, 1);
  }
}

// A focused ant asks rarely, so many visited cities wait in the lists between two queries.
TEST(NearestUnvisited, AgreesWithAScanWhenQueriesAreRare) {
  for (const Instance& instance : grid_cases()) {
    SCOPED_TRACE(instance.name());
    const SpatialGrid grid(instance.coords());
    for (const SpatialGrid* g : {&grid, static_cast<const SpatialGrid*>(nullptr)})
      for (std::size_t spacing : {std::size_t{7}, std::size_t{61}}) {
        NearestUnvisited search(&instance, g);
        expect_agrees_with_brute_force(instance, search, spacing);
      }
  }
}

/// TspProblem without the fast fallback: the engine falls back to its O(n) scan.
struct ScanOnly {
  const TspProblem* p;
  std::size_t size() const { return p->size(); }
  double distance(std::uint32_t i, std::uint32_t j) const { return p->distance(i, j); }
  std::span<const std::uint32_t> candidates(std::uint32_t i) const { return p->candidates(i); }
  double cost(std::span<const std::uint32_t> t) const { return p->cost(t); }
};
static_assert(aco::PermutationProblemWithNearestSearch<TspProblem>);
static_assert(!aco::PermutationProblemWithNearestSearch<ScanOnly>);

TEST(NearestUnvisited, ConstructionBuildsTheSameToursAsTheEngineScan) {
  const TspProblem problem(testing::random_instance(300, 4, EdgeWeightType::euc_2d),
                           {.candidates = 5});
  const ScanOnly scan{&problem};
  aco::PermutationFamily<TspProblem> fast(problem, 1.0, 2.0);
  aco::PermutationFamily<ScanOnly> slow(scan, 1.0, 2.0);
  fast.reserve_ants(1);
  slow.reserve_ants(1);
  fast.trail().fill(1.0);
  slow.trail().fill(1.0);
  fast.prepare(aco::RandomProportional{});
  slow.prepare(aco::RandomProportional{});
  EXPECT_EQ(fast.reference_cost(), slow.reference_cost());
  // C_nn without building a trail (the hybrid's deposit) is the same greedy tour.
  EXPECT_EQ(aco::PermutationFamily<TspProblem>::nearest_neighbour_cost(problem),
            fast.reference_cost());
  EXPECT_EQ(aco::PermutationFamily<ScanOnly>::nearest_neighbour_cost(scan), slow.reference_cost());
  for (std::uint64_t t = 0; t < 20; ++t) {
    std::vector<std::uint32_t> a, b;
    aco::Rng ra(t), rb(t);
    fast.construct(0, a, ra, aco::RandomProportional{});
    slow.construct(0, b, rb, aco::RandomProportional{});
    ASSERT_EQ(a, b);
  }
}

TEST(TspProblem, MatrixAndOnTheFlyDistancesAgree) {
  const Instance instance = read_instance(testing::data("att532.tsp"));
  const TspProblem with_matrix(instance, {.matrix_limit = 1000});
  const TspProblem without(instance, {.matrix_limit = 0});
  EXPECT_TRUE(with_matrix.has_matrix());
  EXPECT_FALSE(without.has_matrix());
  for (std::uint32_t i = 0; i < instance.size(); i += 7)
    for (std::uint32_t j = 0; j < instance.size(); ++j)
      if (i != j) {
        ASSERT_EQ(with_matrix.distance(i, j), without.distance(i, j));
      }
  for (std::uint32_t i = 0; i < instance.size(); ++i) {
    const auto near = with_matrix.neighbours(i);
    const auto near_d = with_matrix.neighbour_distances(i);
    for (std::size_t r = 0; r < near.size(); ++r)
      ASSERT_EQ(near_d[r], instance.distance(i, near[r]));
  }
}

TEST(TspProblem, CapsListsAtNMinusOneAndRejectsEmptyLists) {
  const TspProblem small(read_instance(testing::fixture("burma14.tsp")),
                         {.candidates = 30, .ls_neighbours = 5});
  EXPECT_EQ(small.candidates(0).size(), 13U);
  EXPECT_EQ(small.neighbours(0).size(), 5U);
  EXPECT_THROW(TspProblem(read_instance(testing::fixture("burma14.tsp")), {.candidates = 0}),
               std::invalid_argument);
}

}  // namespace
}  // namespace antslam::tsp
