// Local search: never lengthens a tour and keeps it a permutation; every move gains; with full
// neighbour lists the result is a true local optimum of its neighbourhood (checked by brute
// force over every 2-opt, node-insertion and 3-opt move); known small results; time budgets.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <numbers>

#include "antslam/tsp/local_search.hpp"
#include "antslam/tsp/tsplib.hpp"
#include "tsp_test_support.hpp"

namespace antslam::tsp {
namespace {

constexpr LocalSearchKind kKinds[] = {LocalSearchKind::two_opt, LocalSearchKind::two_half_opt,
                                      LocalSearchKind::three_opt};
// two_level_from: moves on the array tour (never the two-level one) or always on the two-level.
constexpr std::size_t kRepresentations[] = {1'000'000, 0};

std::vector<std::pair<LocalSearchKind, std::size_t>> every_kind_and_representation() {
  std::vector<std::pair<LocalSearchKind, std::size_t>> all;
  for (LocalSearchKind kind : kKinds)
    for (std::size_t from : kRepresentations) all.emplace_back(kind, from);
  return all;
}

std::vector<Instance> property_cases() {
  std::vector<Instance> cases;
  std::uint64_t seed = 1;
  for (std::size_t n : {4U, 5U, 6U, 7U, 8U, 12U, 20U, 50U, 120U})
    for (EdgeWeightType t : {EdgeWeightType::euc_2d, EdgeWeightType::att})
      cases.push_back(testing::random_instance(n, seed++, t, n < 10 ? 20.0 : 1000.0));
  cases.push_back(read_instance(testing::fixture("gr17.tsp")));
  cases.push_back(read_instance(testing::fixture("burma14.tsp")));
  return cases;
}

TEST(LocalSearch, NeverLengthensKeepsAPermutationAndEveryMoveGains) {
  for (const Instance& instance : property_cases()) {
    const TspProblem problem(instance, {.ls_neighbours = 8});
    for (const auto& [kind, from] : every_kind_and_representation()) {
      SCOPED_TRACE(std::to_string(instance.size()) + " " + std::string(to_string(kind)) + " " +
                   std::to_string(from));
      const TourLocalSearch ls({.kind = kind, .neighbours = 8, .two_level_from = from});
      auto workspace = ls.make_workspace(problem);
      aco::Rng rng(instance.size());
      for (int start = 0; start < 10; ++start) {
        auto tour = testing::random_tour(instance.size(), rng);
        const double before = problem.cost(tour);
        ls.improve(problem, tour, workspace, rng, {});
        ASSERT_TRUE(testing::is_permutation_of_n(tour, instance.size()));
        const double after = problem.cost(tour);
        EXPECT_LE(after, before);
        // Integer distances: each applied move shortens the tour by at least 1.
        EXPECT_GE(before - after, static_cast<double>(workspace.stats.moves));
      }
    }
  }
}

double tour_gain_2opt(const TspProblem& p, const std::vector<std::uint32_t>& t, std::size_t i,
                      std::size_t j) {
  const std::size_t n = t.size();
  const std::uint32_t a = t[i], b = t[(i + 1) % n], c = t[j], d = t[(j + 1) % n];
  return p.distance(a, b) + p.distance(c, d) - p.distance(a, c) - p.distance(b, d);
}

/// Largest gain of any 2-opt move (brute force).
double best_2opt(const TspProblem& p, const std::vector<std::uint32_t>& t) {
  double best = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i)
    for (std::size_t j = i + 2; j < t.size(); ++j)
      if ((j + 1) % t.size() != i) best = std::max(best, tour_gain_2opt(p, t, i, j));
  return best;
}

/// Largest gain of the node insertions 2.5-opt tries (brute force): city x, with tour
/// neighbours p and q, moves next to a city y closer to it than p or q is (the gain criterion
/// of moves.hpp), on either side of y.
double best_insertion(const TspProblem& p, const std::vector<std::uint32_t>& t) {
  const std::size_t n = t.size();
  std::vector<std::size_t> at(n);
  for (std::size_t s = 0; s < n; ++s) at[t[s]] = s;
  double best = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t prev = t[(i + n - 1) % n], x = t[i], next = t[(i + 1) % n];
    const double removal = p.distance(prev, x) + p.distance(x, next) - p.distance(prev, next);
    const double reach = std::max(p.distance(prev, x), p.distance(x, next));
    for (std::uint32_t y = 0; y < n; ++y) {
      if (y == x || !(p.distance(x, y) < reach)) continue;
      for (const std::uint32_t u : {t[(at[y] + 1) % n], t[(at[y] + n - 1) % n]}) {
        if (u == x) continue;
        best = std::max(best, removal + p.distance(y, u) - p.distance(y, x) - p.distance(x, u));
      }
    }
  }
  return best;
}

/// Largest gain of any pure 3-opt reconnection of three removed edges (brute force): the tour
/// is X A B with A = t[i+1..j], B = t[j+1..k]; the reconnections X A'B', X B A, X B A', X B'A.
double best_3opt(const TspProblem& p, const std::vector<std::uint32_t>& t) {
  const std::size_t n = t.size();
  const auto d = [&](std::uint32_t u, std::uint32_t v) { return p.distance(u, v); };
  double best = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k) {
        if ((k + 1) % n == i) continue;  // X would be empty
        const std::uint32_t a = t[i], b = t[i + 1], c = t[j], e = t[k], f = t[(k + 1) % n];
        if (j + 1 > k) continue;
        const std::uint32_t g = t[j + 1];  // B starts at g
        const double removed = d(a, b) + d(c, g) + d(e, f);
        for (double added : {d(a, c) + d(b, e) + d(g, f), d(a, g) + d(e, b) + d(c, f),
                             d(a, g) + d(e, c) + d(b, f), d(a, e) + d(g, b) + d(c, f)})
          best = std::max(best, removed - added);
      }
  return best;
}

TEST(LocalSearch, WithFullListsReachesATrueLocalOptimum) {
  for (std::size_t n : {6U, 9U, 13U, 18U, 25U}) {
    for (EdgeWeightType type : {EdgeWeightType::euc_2d, EdgeWeightType::att}) {
      const TspProblem problem(testing::random_instance(n, 100 + n, type), {.ls_neighbours = n});
      for (const auto& [kind, from] : every_kind_and_representation()) {
        SCOPED_TRACE(std::to_string(n) + " " + std::string(to_string(kind)) + " " +
                     std::to_string(from));
        const TourLocalSearch ls(
            {.kind = kind, .neighbours = n, .queue_changed_only = false, .two_level_from = from});
        auto workspace = ls.make_workspace(problem);
        aco::Rng rng(n);
        for (int start = 0; start < 5; ++start) {
          auto tour = testing::random_tour(n, rng);
          do {  // don't-look bits may stop early; a pass without moves proves the optimum
            ls.improve(problem, tour, workspace, rng, {});
          } while (workspace.stats.moves > 0);
          EXPECT_EQ(best_2opt(problem, tour), 0.0);
          if (kind != LocalSearchKind::two_opt) {
            EXPECT_EQ(best_insertion(problem, tour), 0.0);
          }
          if (kind == LocalSearchKind::three_opt) {
            EXPECT_EQ(best_3opt(problem, tour), 0.0);
          }
        }
      }
    }
  }
}

TEST(LocalSearch, TwoOptTurnsACrossedPolygonIntoItsPerimeter) {
  // 12 points on a circle: the only tour without crossings visits them in angular order.
  const std::size_t n = 12;
  std::vector<Point> points;
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    points.push_back({1000.0 * std::cos(angle), 1000.0 * std::sin(angle)});
  }
  const TspProblem problem(Instance("circle", EdgeWeightType::euc_2d, points),
                           {.ls_neighbours = 11});
  const TourLocalSearch ls({.kind = LocalSearchKind::two_opt, .neighbours = 11});
  auto workspace = ls.make_workspace(problem);
  aco::Rng rng(1);
  std::vector<std::uint32_t> tour = {0, 6, 1, 7, 2, 8, 3, 9, 4, 10, 5, 11};  // a star
  ls.improve(problem, tour, workspace, rng, {});
  const double side = distance::euc_2d(points[0], points[1]);  // every side rounds the same
  EXPECT_EQ(problem.cost(tour), 12.0 * side);
  for (std::size_t s = 0; s < n; ++s) {  // consecutive tour cities are neighbours on the circle
    const std::size_t gap = (tour[(s + 1) % n] + n - tour[s]) % n;
    EXPECT_TRUE(gap == 1 || gap == n - 1);
  }
}

TEST(LocalSearch, ThreeOptFindsTheOptimumOfSmallInstancesOften) {
  int hits_3opt = 0, hits_2opt = 0, trials = 0;
  for (std::uint64_t seed = 0; seed < 6; ++seed) {
    const Instance instance = testing::random_instance(11, 500 + seed, EdgeWeightType::euc_2d);
    const double optimum = testing::held_karp(instance);
    const TspProblem problem(instance, {.ls_neighbours = 10});
    const TourLocalSearch three({.kind = LocalSearchKind::three_opt, .neighbours = 10});
    const TourLocalSearch two({.kind = LocalSearchKind::two_opt, .neighbours = 10});
    auto w3 = three.make_workspace(problem);
    auto w2 = two.make_workspace(problem);
    aco::Rng rng(seed);
    for (int start = 0; start < 20; ++start, ++trials) {
      auto a = testing::random_tour(11, rng);
      auto b = a;
      three.improve(problem, a, w3, rng, {});
      two.improve(problem, b, w2, rng, {});
      EXPECT_GE(problem.cost(a), optimum);
      hits_3opt += problem.cost(a) == optimum ? 1 : 0;
      hits_2opt += problem.cost(b) == optimum ? 1 : 0;
    }
  }
  EXPECT_GE(hits_3opt, trials / 2) << "2-opt hit " << hits_2opt;
  EXPECT_GT(hits_3opt, hits_2opt);
}

TEST(LocalSearch, StopsAtAnExpiredToken) {
  const TspProblem problem(testing::random_instance(3000, 8, EdgeWeightType::euc_2d),
                           {.matrix_limit = 0});
  const TourLocalSearch ls;
  auto workspace = ls.make_workspace(problem);
  aco::Rng rng(1);
  auto tour = testing::random_tour(problem.size(), rng);
  const double before = problem.cost(tour);
  const aco::StopToken expired(aco::StopToken::Clock::now() - std::chrono::seconds(1),
                               std::numeric_limits<double>::infinity());
  ls.improve(problem, tour, workspace, rng, expired);
  EXPECT_TRUE(workspace.stats.stopped);
  // The first poll: after 64 cities or 16 moves.
  EXPECT_LE(workspace.stats.examined, 64U);
  EXPECT_LE(workspace.stats.moves, 16U);
  EXPECT_TRUE(testing::is_permutation_of_n(tour, problem.size()));
  EXPECT_LE(problem.cost(tour), before);
  const aco::StopToken cpu_expired(aco::StopToken::Clock::time_point::max(), 0.0);
  auto fresh = ls.make_workspace(problem);
  ls.improve(problem, tour, fresh, rng, cpu_expired);
  EXPECT_TRUE(fresh.stats.stopped);
}

TEST(LocalSearch, StartsFromChangedCitiesOnly) {
  const TspProblem problem(read_instance(testing::data("kroA100.tsp")));
  const TourLocalSearch ls;
  auto workspace = ls.make_workspace(problem);
  aco::Rng rng(4);
  auto tour = testing::random_tour(problem.size(), rng);
  ls.improve(problem, tour, workspace, rng, {});
  EXPECT_EQ(workspace.stats.examined > 0, true);
  auto again = tour;
  ls.improve(problem, again, workspace, rng, {});  // nothing changed: nothing to examine
  EXPECT_EQ(workspace.stats.examined, 0U);
  EXPECT_EQ(again, tour);
  // A double bridge (0 A B C D -> 0 A C B D) changes three edges: only their six end cities
  // start active.
  const auto q = static_cast<std::ptrdiff_t>(problem.size() / 4);
  std::vector<std::uint32_t> kicked(tour.begin(), tour.begin() + q + 1);
  kicked.insert(kicked.end(), tour.begin() + 2 * q + 1, tour.begin() + 3 * q + 1);
  kicked.insert(kicked.end(), tour.begin() + q + 1, tour.begin() + 2 * q + 1);
  kicked.insert(kicked.end(), tour.begin() + 3 * q + 1, tour.end());
  ASSERT_TRUE(testing::is_permutation_of_n(kicked, problem.size()));
  const double kicked_length = problem.cost(kicked);
  ls.improve(problem, kicked, workspace, rng, {});
  EXPECT_TRUE(testing::is_permutation_of_n(kicked, problem.size()));
  EXPECT_LE(problem.cost(kicked), kicked_length);
  EXPECT_GE(workspace.stats.examined, 6U);
}

/// 0 A B C D -> 0 A C B D with four equal quarters; `added` gets its three new edges.
std::vector<std::uint32_t> double_bridge(const std::vector<std::uint32_t>& tour,
                                         std::vector<std::uint32_t>& added) {
  const std::size_t q = tour.size() / 4;
  const auto at = [&](std::size_t p) { return tour.begin() + static_cast<std::ptrdiff_t>(p); };
  std::vector<std::uint32_t> kicked(tour.begin(), at(q + 1));
  kicked.insert(kicked.end(), at(2 * q + 1), at(3 * q + 1));
  kicked.insert(kicked.end(), at(q + 1), at(2 * q + 1));
  kicked.insert(kicked.end(), at(3 * q + 1), tour.end());
  added = {tour[q], tour[2 * q + 1], tour[3 * q], tour[q + 1], tour[2 * q], tour[3 * q + 1]};
  return kicked;
}

TEST(LocalSearch, StartsFromTheEndpointsOfNewEdgesOnly) {
  // A local optimum of 2000 cities, kicked by a double bridge: the search from the six end
  // cities of the three new edges examines a few hundred cities at most, not all 2000, and never
  // lengthens the tour.
  const TspProblem problem(testing::random_instance(2000, 5, EdgeWeightType::euc_2d));
  for (LocalSearchKind kind : kKinds) {
    SCOPED_TRACE(std::string(to_string(kind)));
    const TourLocalSearch ls({.kind = kind});
    auto workspace = ls.make_workspace(problem);
    aco::Rng rng(2);
    auto tour = testing::random_tour(problem.size(), rng);
    ls.improve(problem, tour, workspace, rng, {});
    std::vector<std::uint32_t> added;
    auto kicked = double_bridge(tour, added);
    ASSERT_TRUE(testing::is_permutation_of_n(kicked, problem.size()));
    const double kicked_length = problem.cost(kicked);
    ls.improve(problem, kicked, workspace, rng, {}, added);
    EXPECT_TRUE(testing::is_permutation_of_n(kicked, problem.size()));
    EXPECT_LE(problem.cost(kicked), kicked_length);
    EXPECT_GE(workspace.stats.examined, 6U);
    EXPECT_LT(workspace.stats.examined, problem.size() / 4);
    auto again = kicked;  // no new edges: nothing to examine, nothing changes
    ls.improve(problem, again, workspace, rng, {}, {});
    EXPECT_EQ(workspace.stats.examined, 0U);
    EXPECT_EQ(again, kicked);
  }
}

TEST(LocalSearch, AStoppedSearchFromNewEdgesLeavesNoCityQueued) {
  const TspProblem problem(testing::random_instance(500, 6, EdgeWeightType::euc_2d));
  const TourLocalSearch ls;
  auto workspace = ls.make_workspace(problem);
  aco::Rng rng(3);
  auto tour = testing::random_tour(problem.size(), rng);
  std::vector<std::uint32_t> every_edge;  // a random tour: call every edge new
  for (std::size_t p = 0; p < tour.size(); ++p) {
    every_edge.push_back(tour[p]);
    every_edge.push_back(tour[(p + 1) % tour.size()]);
  }
  const aco::StopToken expired(aco::StopToken::Clock::now() - std::chrono::seconds(1),
                               std::numeric_limits<double>::infinity());
  ls.improve(problem, tour, workspace, rng, expired, every_edge);
  EXPECT_TRUE(workspace.stats.stopped);
  EXPECT_TRUE(testing::is_permutation_of_n(tour, problem.size()));
  ls.improve(problem, tour, workspace, rng, {}, {});
  EXPECT_EQ(workspace.stats.examined, 0U);
  std::vector<std::uint32_t> out_of_range{0, 500};
  EXPECT_THROW(ls.improve(problem, tour, workspace, rng, {}, out_of_range), std::invalid_argument);
}

TEST(ArrayTour, ReversalsKeepPositionsAndEdgeLengthsConsistent) {
  for (std::size_t n : {5U, 6U, 31U}) {
    const TspProblem problem(testing::random_instance(n, 77, EdgeWeightType::euc_2d));
    aco::Rng rng(n);
    ArrayTour tour;
    tour.assign(testing::random_tour(n, rng), problem);
    for (int step = 0; step < 500; ++step) {
      const auto a = rng.below(static_cast<std::uint32_t>(n));
      const auto b = rng.below(static_cast<std::uint32_t>(n));
      const std::vector<std::uint32_t> expected = testing::reversed_path(tour.cities(), a, b);
      tour.reverse_path(a, b);
      // Same cycle as `expected`, in either orientation, from any start.
      const std::uint32_t first = expected[0];
      const bool forward = tour.succ(first) == expected[1];
      std::uint32_t c = first;
      for (std::size_t s = 0; s < n; ++s, c = tour.next(c, forward)) ASSERT_EQ(c, expected[s]);
      for (std::uint32_t x = 0; x < n; ++x) {
        ASSERT_EQ(tour.cities()[tour.position(x)], x);
        ASSERT_EQ(tour.next_length(x, true), problem.distance(x, tour.succ(x)));
        ASSERT_EQ(tour.next_length(x, false), problem.distance(x, tour.pred(x)));
      }
    }
  }
}

TEST(LocalSearch, NamesRoundTrip) {
  for (LocalSearchKind k : {LocalSearchKind::none, LocalSearchKind::two_opt,
                            LocalSearchKind::two_half_opt, LocalSearchKind::three_opt})
    EXPECT_EQ(parse_local_search(to_string(k)), k);
  EXPECT_FALSE(parse_local_search("lk").has_value());
}

}  // namespace
}  // namespace antslam::tsp
