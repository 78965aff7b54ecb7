// Maximum clique: the exact branch and bound against enumeration and on graphs whose maximum is
// known, the greedy clique, the colouring bound, and the ants.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "antslam/clique/aco_search.hpp"
#include "antslam/clique/exact.hpp"
#include "antslam/clique/greedy.hpp"
#include "antslam/clique/local_search.hpp"
#include "antslam/clique/problem.hpp"
#include "antslam/clique/reduction.hpp"
#include "clique_support.hpp"

namespace antslam::clique {
namespace {

using testing::brute_force_maximum;
using testing::random_graph;

Graph complete_graph(std::size_t n) {
  std::vector<Edge> edges;
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = i + 1; j < n; ++j) edges.emplace_back(i, j);
  return Graph(n, edges);
}

/// The Groetzsch graph (Mycielski graph of the 5-cycle): 11 vertices, no triangle, chromatic
/// number 4, so the colouring bound is loose and the search must prove 2 by branching.
Graph groetzsch_graph() {
  std::vector<Edge> edges;
  for (std::uint32_t i = 0; i < 5; ++i) {
    edges.emplace_back(i, (i + 1) % 5);      // the outer 5-cycle
    edges.emplace_back(5 + i, (i + 1) % 5);  // u_i to the cycle neighbours of v_i
    edges.emplace_back(5 + i, (i + 4) % 5);
    edges.emplace_back(5 + i, 10);  // u_i to the hub
  }
  return Graph(11, edges);
}

TEST(Graph, StoresAdjacencyBothWays) {
  const std::vector<Edge> edges{{0, 1}, {2, 1}, {0, 1}, {3, 0}};
  const Graph g(70, edges);
  EXPECT_EQ(g.edge_count(), 3U);
  EXPECT_TRUE(g.adjacent(1, 2));
  EXPECT_TRUE(g.adjacent(2, 1));
  EXPECT_FALSE(g.adjacent(2, 3));
  EXPECT_EQ(g.degree(0), 2U);
  EXPECT_EQ(std::vector<std::uint32_t>(g.neighbours(0).begin(), g.neighbours(0).end()),
            (std::vector<std::uint32_t>{1, 3}));
  EXPECT_EQ(g.words(), 2U);
  EXPECT_TRUE(g.unit_weights());
  EXPECT_EQ(g.total_weight(), 70.0);
}

TEST(Graph, RejectsBadInput) {
  const std::vector<Edge> loop{{2, 2}};
  EXPECT_THROW(Graph(3, loop), std::invalid_argument);
  const std::vector<Edge> outside{{0, 3}};
  EXPECT_THROW(Graph(3, outside), std::invalid_argument);
  EXPECT_THROW(Graph(2, {}, {1.0}), std::invalid_argument);
  EXPECT_THROW(Graph(2, {}, {1.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(Graph(2, {}, {1.0, std::nan("")}), std::invalid_argument);
}

TEST(Graph, CliquePredicates) {
  const Graph g = groetzsch_graph();
  const std::vector<std::uint32_t> edge{0, 1}, triangle{0, 1, 2}, repeated{0, 0};
  EXPECT_TRUE(is_clique(g, edge));
  EXPECT_FALSE(is_clique(g, triangle));
  EXPECT_FALSE(is_clique(g, repeated));
  EXPECT_TRUE(is_maximal_clique(g, edge));  // triangle-free: every edge is maximal
  EXPECT_FALSE(is_maximal_clique(g, std::vector<std::uint32_t>{0}));
}

TEST(Exact, KnownMaxima) {
  EXPECT_EQ(maximum_clique_exact(complete_graph(9)).clique.weight, 9.0);
  EXPECT_EQ(maximum_clique_exact(Graph(5, {})).clique.weight, 1.0);
  const ExactResult g = maximum_clique_exact(groetzsch_graph());
  EXPECT_EQ(g.clique.weight, 2.0);
  EXPECT_TRUE(g.clique.optimal);
  EXPECT_EQ(colouring_bound(groetzsch_graph()), 4.0);  // chromatic number 4: the bound is loose
  // Weighted: the heaviest vertex of an edgeless graph.
  EXPECT_EQ(maximum_clique_exact(Graph(3, {}, {2.0, 7.0, 3.0})).clique.vertices,
            std::vector<std::uint32_t>{1});
}

TEST(Exact, FindsAPlantedClique) {
  const std::vector<std::uint32_t> planted{3, 17, 25, 40, 41, 58, 77, 90, 102, 115, 130, 149};
  const Graph g = random_graph(150, 0.1, 5, 1, planted);
  const ExactResult r = maximum_clique_exact(g);
  EXPECT_TRUE(r.clique.optimal);
  EXPECT_EQ(r.clique.vertices, planted);  // G(150, 0.1) alone has cliques of about 4
  EXPECT_TRUE(is_clique(g, r.clique.vertices));
}

class SmallRandomGraph : public ::testing::TestWithParam<int> {};

TEST_P(SmallRandomGraph, ExactEqualsEnumeration) {
  for (int max_weight : {1, 9}) {
    const auto seed = static_cast<std::uint64_t>(GetParam());
    const Graph g = random_graph(14, 0.2 + 0.05 * (GetParam() % 12), seed, max_weight);
    const double optimum = brute_force_maximum(g);
    const ExactResult exact = maximum_clique_exact(g);
    EXPECT_TRUE(exact.clique.optimal);
    EXPECT_EQ(exact.clique.weight, optimum);
    EXPECT_EQ(exact.clique.upper_bound, optimum);
    EXPECT_TRUE(is_clique(g, exact.clique.vertices));
    EXPECT_EQ(weight_of(g, exact.clique.vertices), optimum);

    const CliqueResult greedy = greedy_clique(g);
    EXPECT_TRUE(is_maximal_clique(g, greedy.vertices));
    EXPECT_LE(greedy.weight, optimum);
    EXPECT_GE(greedy.upper_bound, optimum);
    EXPECT_GE(colouring_bound(g), optimum);
  }
}

TEST_P(SmallRandomGraph, AntsFindTheMaximum) {
  const auto seed = static_cast<std::uint64_t>(GetParam());
  const Graph g = random_graph(18, 0.5, seed + 100, 5);
  const double optimum = brute_force_maximum(g);
  AcoSearchSettings s;
  s.parameters.seed = seed;
  s.termination = {.max_iterations = 200};
  const AcoSearchResult r = maximum_clique_aco(g, s);
  EXPECT_TRUE(is_maximal_clique(g, r.clique.vertices));
  EXPECT_EQ(r.clique.weight, optimum);
  EXPECT_GE(r.clique.upper_bound, optimum);
}

TEST_P(SmallRandomGraph, ExactFromAGivenCliqueEqualsEnumeration) {
  // Started from a single vertex, the greedy clique or a maximum one, branch and bound ends at
  // the maximum; a heavier start prunes at least as much (the same branching, a higher bound).
  const auto seed = static_cast<std::uint64_t>(GetParam());
  const Graph g = random_graph(16, 0.5, seed + 300, 4);
  const double optimum = brute_force_maximum(g);
  const ExactResult plain = maximum_clique_exact(g);
  const std::vector<std::uint32_t> one{7};
  for (const std::vector<std::uint32_t>& start :
       {one, greedy_clique(g).vertices, plain.clique.vertices}) {
    const ExactResult r = maximum_clique_exact(g, {}, start);
    EXPECT_TRUE(r.clique.optimal);
    EXPECT_EQ(r.clique.weight, optimum);
    EXPECT_TRUE(is_clique(g, r.clique.vertices));
  }
  EXPECT_LE(maximum_clique_exact(g, {}, plain.clique.vertices).nodes, plain.nodes);
}

TEST(Exact, KeepsAGivenMaximumCliqueRatherThanAnotherOfTheSameWeight) {
  // Two disjoint triangles: the greedy clique is one of them; started from the other, branch and
  // bound proves it maximum and returns it, not the greedy one.
  const std::vector<Edge> edges{{0, 1}, {0, 2}, {1, 2}, {3, 4}, {3, 5}, {4, 5}};
  const Graph g(6, edges);
  const std::vector<std::uint32_t> greedy = greedy_clique(g).vertices;
  const std::vector<std::uint32_t> other = greedy.front() < 3 ? std::vector<std::uint32_t>{3, 4, 5}
                                                              : std::vector<std::uint32_t>{0, 1, 2};
  const ExactResult r = maximum_clique_exact(g, {}, other);
  EXPECT_TRUE(r.clique.optimal);
  EXPECT_EQ(r.clique.vertices, other);
}

TEST_P(SmallRandomGraph, ProofNodesProveTheAntsCliqueOrFindTheMaximum) {
  // One ant, one iteration, no local search: often short of the maximum; branch and bound from
  // its clique then reaches the maximum and proves it, and never returns a lighter clique.
  const auto seed = static_cast<std::uint64_t>(GetParam());
  const Graph g = random_graph(18, 0.5, seed + 100, 5);
  const double optimum = brute_force_maximum(g);
  AcoSearchSettings s;
  s.parameters.seed = seed;
  s.parameters.ants = 1;
  s.local_search = false;
  s.termination = {.max_iterations = 1};
  s.proof_nodes = 0;
  const AcoSearchResult alone = maximum_clique_aco(g, s);
  s.proof_nodes = 1'000'000;
  const AcoSearchResult proved = maximum_clique_aco(g, s);
  EXPECT_EQ(proved.iterations, alone.iterations);
  EXPECT_EQ(proved.clique.weight, optimum);
  EXPECT_TRUE(proved.clique.optimal);
  EXPECT_EQ(proved.clique.upper_bound, optimum);
  EXPECT_TRUE(is_clique(g, proved.clique.vertices));
  EXPECT_EQ(alone.proof_nodes, 0U);
  EXPECT_GT(proved.proof_nodes + (alone.clique.optimal ? 1U : 0U), 0U);
}

INSTANTIATE_TEST_SUITE_P(Seeds, SmallRandomGraph, ::testing::Range(1, 25));

// Dense graphs with a planted clique, as consistency graphs whose closures mostly agree: the
// search on the residual finds the maximum, and every maximum clique holds the universal vertices.
TEST_P(SmallRandomGraph, ReducedSearchEqualsEnumeration) {
  const auto seed = static_cast<std::uint64_t>(GetParam());
  const Graph g = random_graph(16, 0.3 + 0.04 * (GetParam() % 16), seed + 200, 1, {1, 4, 6, 9, 12});
  const double optimum = brute_force_maximum(g);
  const CliqueReduction reduction = reduce_for_maximum_clique(g);
  EXPECT_TRUE(is_clique(g, reduction.greedy));
  const CliqueResult r = maximum_clique_reduced(
      g, reduction, [](const Graph& residual) { return maximum_clique_exact(residual).clique; });
  EXPECT_TRUE(is_clique(g, r.vertices));
  EXPECT_EQ(r.weight, optimum);
  EXPECT_TRUE(r.optimal);
  EXPECT_EQ(r.upper_bound, optimum);
  // Every maximum clique (by enumeration) holds every universal vertex.
  for (std::uint32_t mask = 1; mask < (1U << g.size()); ++mask) {
    std::vector<std::uint32_t> subset;
    for (std::uint32_t v = 0; v < g.size(); ++v)
      if ((mask >> v) & 1U) subset.push_back(v);
    if (static_cast<double>(subset.size()) != optimum || !is_clique(g, subset)) continue;
    for (const std::uint32_t u : reduction.universal)
      EXPECT_TRUE(std::binary_search(subset.begin(), subset.end(), u)) << u;
  }
}

TEST(Reduction, KeepsTheUniversalVerticesAndSearchesTheRest) {
  // K5 without the edge 0-1: 2, 3 and 4 are in every maximum clique, 0 or 1 completes it.
  std::vector<Edge> edges;
  for (std::uint32_t i = 0; i < 5; ++i)
    for (std::uint32_t j = i + 1; j < 5; ++j)
      if (!(i == 0 && j == 1)) edges.emplace_back(i, j);
  const Graph g(5, edges);
  const CliqueReduction reduction = reduce_for_maximum_clique(g);
  EXPECT_EQ(reduction.greedy, (std::vector<std::uint32_t>{0, 2, 3, 4}));
  EXPECT_EQ(reduction.universal, (std::vector<std::uint32_t>{2, 3, 4}));
  EXPECT_EQ(reduction.residual, (std::vector<std::uint32_t>{0, 1}));
  std::size_t searched = 0;
  const CliqueResult r = maximum_clique_reduced(g, reduction, [&](const Graph& residual) {
    searched = residual.size();
    EXPECT_EQ(residual.edge_count(), 0U);  // 0 and 1 are not adjacent
    return maximum_clique_exact(residual).clique;
  });
  EXPECT_EQ(searched, 2U);
  EXPECT_EQ(r.vertices, (std::vector<std::uint32_t>{0, 2, 3, 4}));
  EXPECT_TRUE(r.optimal);
}

TEST(Reduction, RemovesWhatCannotBeInALargerCliqueAndNeedsNoSearchThen) {
  // K4 on 0..3 and vertex 4 adjacent to 0 only: 4 has degree 1 < 4 - 1 and goes; the rest is
  // complete, so the maximum needs no search.
  std::vector<Edge> edges{{0, 4}};
  for (std::uint32_t i = 0; i < 4; ++i)
    for (std::uint32_t j = i + 1; j < 4; ++j) edges.emplace_back(i, j);
  const Graph g(5, edges);
  const CliqueReduction reduction = reduce_for_maximum_clique(g);
  EXPECT_EQ(reduction.universal, (std::vector<std::uint32_t>{0, 1, 2, 3}));
  EXPECT_TRUE(reduction.residual.empty());
  bool searched = false;
  const CliqueResult r = maximum_clique_reduced(g, reduction, [&](const Graph& residual) {
    searched = true;
    return maximum_clique_exact(residual).clique;
  });
  EXPECT_FALSE(searched);
  EXPECT_EQ(r.vertices, (std::vector<std::uint32_t>{0, 1, 2, 3}));
  EXPECT_EQ(r.upper_bound, 4.0);
  EXPECT_TRUE(r.optimal);
}

TEST(Reduction, RefusesWeightsAndBadVertexLists) {
  const Graph weighted(2, std::vector<Edge>{{0, 1}}, {1.0, 2.0});
  EXPECT_THROW(reduce_for_maximum_clique(weighted), std::invalid_argument);
  const Graph g(3, std::vector<Edge>{{0, 1}});
  const std::vector<std::uint32_t> unsorted{1, 0}, outside{0, 3};
  EXPECT_THROW(induced_subgraph(g, unsorted), std::invalid_argument);
  EXPECT_THROW(induced_subgraph(g, outside), std::invalid_argument);
  const std::vector<std::uint32_t> both{0, 1};
  EXPECT_EQ(induced_subgraph(g, both).edge_count(), 1U);
}

TEST(Exact, StopsAtTheTimeLimitWithAValidClique) {
  const Graph g = random_graph(400, 0.9, 3);  // far beyond a millisecond of branch and bound
  const ExactResult r = maximum_clique_exact(g, {.time_limit_s = 0.001});
  EXPECT_FALSE(r.clique.optimal);
  EXPECT_TRUE(is_clique(g, r.clique.vertices));
  EXPECT_GE(r.clique.upper_bound, r.clique.weight);
  EXPECT_THROW(maximum_clique_exact(g, {.time_limit_s = -1.0}), std::invalid_argument);
}

TEST(Exact, StopsAtTheNodeBudgetTheSameWayEveryTime) {
  const Graph g = random_graph(400, 0.9, 3);
  const ExactResult a = maximum_clique_exact(g, {.time_limit_s = 0.0, .max_nodes = 500});
  const ExactResult b = maximum_clique_exact(g, {.time_limit_s = 0.0, .max_nodes = 500});
  EXPECT_FALSE(a.clique.optimal);
  EXPECT_EQ(a.nodes, 501U);  // the node that exceeds the budget stops the search
  EXPECT_EQ(a.clique.vertices, b.clique.vertices);
  EXPECT_EQ(a.nodes, b.nodes);
  EXPECT_TRUE(is_clique(g, a.clique.vertices));
  const std::vector<std::uint32_t> not_a_clique{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
  ASSERT_FALSE(is_clique(g, not_a_clique));
  EXPECT_THROW(maximum_clique_exact(g, {}, not_a_clique), std::invalid_argument);
  const std::vector<std::uint32_t> outside{400};
  EXPECT_THROW(maximum_clique_exact(g, {}, outside), std::invalid_argument);
}

TEST(Aco, StopsAtTheColouringBound) {
  const Graph g = complete_graph(30);  // the bound is 30 and the first ant reaches it
  const AcoSearchResult r = maximum_clique_aco(g);
  EXPECT_EQ(r.clique.weight, 30.0);
  EXPECT_TRUE(r.clique.optimal);
  EXPECT_EQ(r.reason, aco::StopReason::target);
  EXPECT_EQ(r.iterations, 1U);
}

TEST(Graph, RejectsMoreVerticesThanItsIndicesHold) {
  EXPECT_THROW(Graph(std::size_t{1} << 32U, {}), std::length_error);  // no allocation tried
}

TEST(Aco, RejectsAnUnboundedRunAndAnEmptyGraph) {
  AcoSearchSettings s;
  s.termination = {};
  EXPECT_THROW(maximum_clique_aco(complete_graph(3), s), std::invalid_argument);
  EXPECT_THROW(maximum_clique_aco(Graph(0, {})), std::invalid_argument);
}

// Clique {0, 1, 2} is maximal; 3 and 4 are adjacent to each other and to 0 and 1 but not to 2:
// the (1,2)-swap trades 2 for 3 and 4, then 5 (adjacent to 0, 1, 3, 4) is added.
Graph swap_graph(std::vector<double> weights) {
  const std::vector<Edge> edges{{0, 1}, {0, 2}, {1, 2}, {0, 3}, {1, 3}, {0, 4}, {1, 4},
                                {3, 4}, {0, 5}, {1, 5}, {3, 5}, {4, 5}, {2, 6}};
  return Graph(7, edges, std::move(weights));
}

TEST(LocalSearch, SwapsOneForTwoAndStaysMaximal) {
  const Graph g = swap_graph({});
  const CliqueProblem p(g);
  const SwapLocalSearch ls;
  SwapLocalSearch::Workspace ws = ls.make_workspace(p);
  aco::Rng rng(1);
  std::vector<std::uint32_t> clique{0, 1, 2};
  ASSERT_TRUE(is_maximal_clique(g, clique));
  ls.improve(p, clique, ws, rng, {});
  std::sort(clique.begin(), clique.end());
  EXPECT_EQ(clique, (std::vector<std::uint32_t>{0, 1, 3, 4, 5}));
  EXPECT_TRUE(is_maximal_clique(g, clique));
}

TEST(LocalSearch, KeepsAHeavierVertex) {
  const Graph g = swap_graph({1, 1, 9, 1, 1, 1, 1});  // 2 outweighs 3 + 4 (+ 5)
  const CliqueProblem p(g);
  const SwapLocalSearch ls;
  SwapLocalSearch::Workspace ws = ls.make_workspace(p);
  aco::Rng rng(1);
  std::vector<std::uint32_t> clique{0, 1, 2};
  ls.improve(p, clique, ws, rng, {});
  EXPECT_EQ(clique, (std::vector<std::uint32_t>{0, 1, 2}));
}

TEST(LocalSearch, NeverLighterAlwaysMaximalOnRandomGraphs) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Graph g = random_graph(40, 0.6, seed, 3);
    const CliqueProblem p(g);
    const SwapLocalSearch ls;
    SwapLocalSearch::Workspace ws = ls.make_workspace(p);
    aco::Rng rng(seed);
    std::vector<std::uint32_t> clique{static_cast<std::uint32_t>(seed)};  // grown to maximal
    for (std::uint32_t v = 0; v < g.size(); ++v)
      if (std::all_of(clique.begin(), clique.end(),
                      [&](std::uint32_t c) { return g.adjacent(c, v); }))
        clique.push_back(v);
    const double before = weight_of(g, clique);
    ls.improve(p, clique, ws, rng, {});
    EXPECT_TRUE(is_maximal_clique(g, clique));
    EXPECT_GE(weight_of(g, clique), before);
  }
}

// Clique {0, 1, 2} is maximal and no (1,2)-swap applies: 3 is the only 1-tight vertex (it misses
// 2), and 4 and 5 miss both 1 and 2. The plateau move 2 -> 3 makes 4 and 5 1-tight with the
// same missed member 1, and the (1,2)-swap then gives {0, 3, 4, 5}.
Graph plateau_graph(std::vector<double> weights) {
  const std::vector<Edge> edges{{0, 1}, {0, 2}, {1, 2}, {0, 3}, {1, 3},
                                {0, 4}, {3, 4}, {0, 5}, {3, 5}, {4, 5}};
  return Graph(6, edges, std::move(weights));
}

std::vector<std::uint32_t> improved(const Graph& g, std::vector<std::uint32_t> clique,
                                    std::size_t plateau_steps) {
  const CliqueProblem p(g);
  const SwapLocalSearch ls{.plateau_steps = plateau_steps};
  SwapLocalSearch::Workspace ws = ls.make_workspace(p);
  aco::Rng rng(1);
  ls.improve(p, clique, ws, rng, {});
  std::sort(clique.begin(), clique.end());
  return clique;
}

TEST(LocalSearch, PlateauWalkReachesWhatSwapsCannot) {
  const Graph g = plateau_graph({});
  EXPECT_EQ(improved(g, {0, 1, 2}, 0), (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_EQ(improved(g, {0, 1, 2}, 1), (std::vector<std::uint32_t>{0, 3, 4, 5}));
}

TEST(LocalSearch, PlateauWalkNeverTakesALighterVertex) {
  // 3 is lighter than the 2 it would replace: no plateau move, although {0, 3, 4, 5} weighs 3.5.
  const Graph g = plateau_graph({1, 1, 1, 0.5, 1, 1});
  EXPECT_EQ(improved(g, {0, 1, 2}, 10), (std::vector<std::uint32_t>{0, 1, 2}));
}

TEST(LocalSearch, PlateauWalkThatGainsNothingChangesNothing) {
  // Two triangles on the edge 0-1: the walk goes to {0, 1, 3}, gains nothing, and the clique
  // it started from is kept.
  const Graph g(4, std::vector<Edge>{{0, 1}, {0, 2}, {1, 2}, {0, 3}, {1, 3}});
  EXPECT_EQ(improved(g, {0, 1, 2}, 5), (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_EQ(improved(g, {0, 1, 3}, 5), (std::vector<std::uint32_t>{0, 1, 3}));
}

TEST(LocalSearch, PlateauWalkNeverLighterThanTheSwapsAlone) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Graph g = random_graph(60, 0.7, seed, 3);
    std::vector<std::uint32_t> start{static_cast<std::uint32_t>(seed)};  // grown to maximal
    for (std::uint32_t v = 0; v < g.size(); ++v)
      if (v != start.front() && std::all_of(start.begin(), start.end(),
                                            [&](std::uint32_t c) { return g.adjacent(c, v); }))
        start.push_back(v);
    const std::vector<std::uint32_t> swaps = improved(g, start, 0);
    const std::vector<std::uint32_t> walked = improved(g, start, 50);
    EXPECT_TRUE(is_maximal_clique(g, walked));
    EXPECT_GE(weight_of(g, walked), weight_of(g, swaps));
    EXPECT_EQ(improved(g, start, 50), walked);  // deterministic
  }
}

TEST(Problem, CostAndHeuristic) {
  const Graph g(4, std::vector<Edge>{{0, 1}, {1, 2}}, {1.0, 2.0, 3.0, 4.0});
  const CliqueProblem p(g);
  const std::vector<std::uint32_t> clique{1, 2};
  EXPECT_EQ(p.cost(clique), 10.0 - 5.0 + 1.0);
  EXPECT_EQ(p.cost_of_weight(5.0), 6.0);
  EXPECT_EQ(p.heuristic(1), 6.0);  // 2 + its neighbours 1 and 3
  EXPECT_EQ(p.heuristic(3), 4.0);
  EXPECT_TRUE(p.compatible(2, 1));
  EXPECT_FALSE(p.compatible(0, 2));
}

}  // namespace
}  // namespace antslam::clique
