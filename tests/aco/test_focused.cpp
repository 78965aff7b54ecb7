// Focused construction (aco/focused_construction.hpp): a hand-traced tour, the recorded new
// edges against a brute-force count, the source each iteration uses, and MAX-MIN's bounds.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "antslam/aco/colony.hpp"
#include "antslam/aco/focused_construction.hpp"
#include "antslam/aco/rules.hpp"
#include "antslam/aco/synthetic_layered.hpp"
#include "antslam/aco/update_mmas.hpp"
#include "antslam/aco/variants.hpp"
#include "test_problems.hpp"

namespace antslam::aco {
namespace {

using testing::EuclideanTsp;
using testing::is_permutation_of_n;

/// Undirected edges of a closed tour.
std::set<std::pair<std::uint32_t, std::uint32_t>> edges_of(std::span<const std::uint32_t> tour) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (std::size_t p = 0; p < tour.size(); ++p) {
    const std::uint32_t a = tour[p], b = tour[(p + 1) % tour.size()];
    edges.insert({std::min(a, b), std::max(a, b)});
  }
  return edges;
}

/// Tour edges not in `source`, by comparing edge sets.
std::size_t new_edge_count(std::span<const std::uint32_t> tour,
                           std::span<const std::uint32_t> source) {
  const auto ours = edges_of(tour), theirs = edges_of(source);
  std::size_t count = 0;
  for (const auto& e : ours) count += theirs.count(e) == 0 ? 1U : 0U;
  return count;
}

/// Runs build_focused with scripted choices; returns the tour and its new edges.
struct Scripted {
  std::vector<std::uint32_t> tour, new_edges;
  std::vector<std::uint32_t> choices;  // returned by choose(), in order
  std::size_t next_choice = 0;

  void run(const std::vector<std::uint32_t>& source_tour, std::uint32_t start, std::size_t min) {
    SourceTour source;
    source.assign(source_tour);
    const auto n = static_cast<std::uint32_t>(source_tour.size());
    std::vector<bool> visited(n, false);
    build_focused(
        source, n, start, min, [&](std::uint32_t) { return choices.at(next_choice++); },
        [&](std::uint32_t c) {
          tour.push_back(c);
          visited[c] = true;
        },
        [&](std::uint32_t c) { return visited[c]; }, new_edges);
  }
};

TEST(FocusedConstruction, CopiesTheSourceOnceEnoughEdgesAreNew) {
  // Source 0-1-2-3-4-5-6-7-8-9-0. Start at 0, min 2 new edges. The rule picks 5 (new edge 0-5),
  // then 6 (a source edge), then 2 (new 6-2): two new edges, so the ant copies the source from 2
  // forward: 3, 4, then 5 is visited; at 4 the rule picks 8 (new 4-8); copying from 8 forward
  // gives 9, then 0 is visited; the rule picks 7 (new 9-7), copying from 7 forward meets 8
  // (visited) and backward meets 6 (visited), so the rule picks 1 (new 7-1); the closing edge
  // 1-0 is a source edge.
  Scripted s;
  s.choices = {5, 6, 2, 8, 7, 1};
  s.run({0, 1, 2, 3, 4, 5, 6, 7, 8, 9}, 0, 2);
  EXPECT_EQ(s.tour, (std::vector<std::uint32_t>{0, 5, 6, 2, 3, 4, 8, 9, 7, 1}));
  EXPECT_EQ(s.new_edges, (std::vector<std::uint32_t>{0, 5, 6, 2, 4, 8, 9, 7, 7, 1}));
  EXPECT_EQ(s.next_choice, s.choices.size());
}

TEST(FocusedConstruction, CopiesBackwardWhenTheSuccessorIsTaken) {
  // Source 0-1-2-3-4-5-0, start 3, min 1: the rule picks 1 (new 3-1); 1's successor 2 is
  // unvisited, copy 2, then 3 is visited; at 2 both source neighbours are visited, the rule
  // picks 5 (new 2-5); 5's successor 0 is free: copy 0, then 1 is visited; the rule picks 4
  // (new 0-4); the closing edge 4-3 is a source edge.
  Scripted s;
  s.choices = {1, 5, 4};
  s.run({0, 1, 2, 3, 4, 5}, 3, 1);
  EXPECT_EQ(s.tour, (std::vector<std::uint32_t>{3, 1, 2, 5, 0, 4}));
  EXPECT_EQ(s.new_edges, (std::vector<std::uint32_t>{3, 1, 2, 5, 0, 4}));
  // And backward: source 0-1-2-3-4-5-0, start 0, min 1: the rule picks 3 (new 0-3), copy 4, 5
  // forward (then 0 is visited); the rule picks 2 (new 5-2), whose successor 3 is visited but
  // whose predecessor 1 is not: copy 1 backward (then 0 is visited); closing 1-0 is old.
  Scripted b;
  b.choices = {3, 2};
  b.run({0, 1, 2, 3, 4, 5}, 0, 1);
  EXPECT_EQ(b.tour, (std::vector<std::uint32_t>{0, 3, 4, 5, 2, 1}));
  EXPECT_EQ(b.new_edges, (std::vector<std::uint32_t>{0, 3, 5, 2}));
}

TEST(FocusedConstruction, RecordsTheClosingEdgeWhenItIsNew) {
  // Source 0-1-2-3-0, start 0, min 5 (never reached): the rule builds 0, 2, 1, 3; edges 0-2 and
  // 1-3 are new, 2-1 and 3-0 are source edges.
  Scripted s;
  s.choices = {2, 1, 3};
  s.run({0, 1, 2, 3}, 0, 5);
  EXPECT_EQ(s.tour, (std::vector<std::uint32_t>{0, 2, 1, 3}));
  EXPECT_EQ(s.new_edges, (std::vector<std::uint32_t>{0, 2, 1, 3}));
  Scripted c;  // 0, 1, 3, 2: new 1-3 and the closing 2-0
  c.choices = {1, 3, 2};
  c.run({0, 1, 2, 3}, 0, 5);
  EXPECT_EQ(c.new_edges, (std::vector<std::uint32_t>{1, 3, 2, 0}));
}

/// A colony on a 300-city Euclidean TSP with MAX-MIN and focused construction.
auto focused_colony(const EuclideanTsp& problem, double global_best_source) {
  ColonySettings settings{.ants = 6, .seed = 9};
  settings.focused = {.min_new_edges = 4, .global_best_source = global_best_source};
  return Colony<EuclideanTsp, RandomProportional, MaxMinUpdate>(problem, settings, {},
                                                                MaxMinUpdate({.rho = 0.2}));
}

TEST(FocusedConstruction, AntsChangeThePreviousIterationBestInAtLeastTheMinimum) {
  const EuclideanTsp problem(300, 10, 3);
  auto colony = focused_colony(problem, 0.0);  // the source is always the iteration best
  colony.step();
  for (int it = 0; it < 5; ++it) {
    const std::vector<std::uint32_t> source = colony.ants()[colony.ranking().front()].path;
    colony.step();
    for (const Solution& ant : colony.ants()) {
      ASSERT_TRUE(is_permutation_of_n(ant.path, 300));
      const std::size_t changed = new_edge_count(ant.path, source);
      EXPECT_GE(changed, 4U);
      EXPECT_LT(changed, 150U);  // a focused ant keeps most of the source
    }
  }
}

TEST(FocusedConstruction, SourceIsTheBestSoFarWhenAlwaysChosen) {
  const EuclideanTsp problem(300, 10, 3);
  auto colony = focused_colony(problem, 1.0);
  colony.step();
  for (int it = 0; it < 5; ++it) {
    const std::vector<std::uint32_t> source = colony.best().path;
    colony.step();
    for (const Solution& ant : colony.ants()) EXPECT_GE(new_edge_count(ant.path, source), 4U);
  }
}

TEST(FocusedConstruction, FirstIterationBuildsFromNothingAsWithoutFocus) {
  const EuclideanTsp problem(120, 8, 5);
  auto focused = focused_colony(problem, 0.0);
  ColonySettings plain_settings{.ants = 6, .seed = 9};
  Colony<EuclideanTsp, RandomProportional, MaxMinUpdate> plain(problem, plain_settings, {},
                                                               MaxMinUpdate({.rho = 0.2}));
  focused.step();
  plain.step();
  for (std::size_t a = 0; a < 6; ++a) EXPECT_EQ(focused.ants()[a].path, plain.ants()[a].path);
}

TEST(FocusedConstruction, LayeredProblemsRejectIt) {
  const SyntheticLayeredProblem problem(3, 4, 1);
  ColonySettings settings;
  settings.focused.min_new_edges = 2;
  using LayeredColony = Colony<SyntheticLayeredProblem, RandomProportional, MaxMinUpdate>;
  EXPECT_THROW(LayeredColony(problem, settings, {}, MaxMinUpdate()), std::invalid_argument);
}

TEST(FocusedConstruction, MaxMinBoundsOverOneCandidateList) {
  // Eq. 11 of Stuetzle & Hoos with n = avg = k = 10 candidates, p_best 0.05, rho 0.2, C_nn 1000:
  // tau_max = 1/(0.2 * 1000) = 0.005; p = 0.05^(1/10); tau_min = tau_max (1 - p) / (9 p).
  MaxMinUpdate update({.rho = 0.2, .p_best = 0.05});
  std::vector<double> values(4);
  struct Trail {
    std::vector<double>* v;
    void fill(double x) { std::fill(v->begin(), v->end(), x); }
  } trail{&values};
  InitContext context{.reference_cost = 1000.0,
                      .ants = 5,
                      .decisions = 300,
                      .mean_options = 5.5,
                      .local_search = true,
                      .focused = true,
                      .max_options = 10.0};
  update.initialize(trail, context);
  const double p = std::pow(0.05, 0.1);
  EXPECT_DOUBLE_EQ(update.tau_max(), 0.005);
  EXPECT_DOUBLE_EQ(update.tau_min(), 0.005 * (1.0 - p) / (9.0 * p));
  EXPECT_DOUBLE_EQ(values[0], 0.005);
}

TEST(FocusedConstruction, SolveRunsEveryVariantFocused) {
  const EuclideanTsp problem(150, 8, 11);
  for (const Variant v : all_variants()) {
    Parameters p;
    p.variant = v;
    p.ants = 5;
    p.focused = {.min_new_edges = 3, .global_best_source = 0.1};
    const RunResult r = solve(problem, p, {.max_iterations = 15});
    EXPECT_TRUE(is_permutation_of_n(r.best.path, 150)) << to_string(v);
    EXPECT_EQ(r.best.cost, problem.cost(r.best.path));
  }
}

}  // namespace
}  // namespace antslam::aco
