// The TSP on the engine: every variant solves eil51 and berlin52 with local search, results are
// identical on every backend and thread count, and the TSP defaults resolve as documented.

#include <gtest/gtest.h>

#include "antslam/tsp/solver.hpp"
#include "antslam/tsp/tsplib.hpp"
#include "tsp_test_support.hpp"

namespace antslam::tsp {
namespace {

const TspProblem& instance_problem(const std::string& name) {
  static std::map<std::string, std::unique_ptr<TspProblem>> cache;
  auto& slot = cache[name];
  if (!slot) slot = std::make_unique<TspProblem>(read_instance(testing::data(name + ".tsp")));
  return *slot;
}

struct Case {
  aco::Variant variant;
  std::string instance;
  double optimum;
};

class EveryVariantWithLocalSearch : public ::testing::TestWithParam<Case> {};

TEST_P(EveryVariantWithLocalSearch, FindsTheOptimum) {
  const Case& c = GetParam();
  SolverSettings s;
  s.aco.variant = c.variant;
  s.aco.seed = 3;
  s.local_search.kind = LocalSearchKind::three_opt;
  const aco::RunResult r =
      solve(instance_problem(c.instance), s, {.max_iterations = 250, .target_cost = c.optimum});
  EXPECT_EQ(r.best.cost, c.optimum);
  EXPECT_EQ(r.reason, aco::StopReason::target);
}

std::vector<Case> every_variant() {
  std::vector<Case> cases;
  for (const aco::Variant v : aco::all_variants()) {
    cases.push_back({v, "eil51", 426});
    cases.push_back({v, "berlin52", 7542});
  }
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Tsplib, EveryVariantWithLocalSearch, ::testing::ValuesIn(every_variant()),
                         [](const auto& param_info) {
                           return std::string(aco::to_string(param_info.param.variant)) + "_" +
                                  param_info.param.instance;
                         });

TEST(Solver, MmasWithoutLocalSearchGetsCloseOnEil51) {
  SolverSettings s;
  s.local_search.kind = LocalSearchKind::none;
  const aco::RunResult r = solve(instance_problem("eil51"), s, {.max_iterations = 650});
  EXPECT_LE(r.best.cost, 426.0 * 1.01);
  EXPECT_EQ(r.best.cost, instance_problem("eil51").instance().tour_length(r.best.path));
}

struct Configuration {
  aco::Variant variant;
  LocalSearchKind local_search;
  std::size_t two_level_from = LocalSearchSettings{}.two_level_from;
};

class Determinism : public ::testing::TestWithParam<Configuration> {};

TEST_P(Determinism, SameResultOnEveryBackendAndThreadCount) {
  const TspProblem& problem = instance_problem("kroA100");
  SolverSettings s;
  s.aco.variant = GetParam().variant;
  s.aco.ants = 12;
  s.aco.seed = 11;
  s.local_search.kind = GetParam().local_search;
  s.local_search.two_level_from = GetParam().two_level_from;
  const aco::Termination t{.max_iterations = 25};
  const aco::RunResult reference = solve(problem, s, t);
  EXPECT_EQ(reference.settings.backend, aco::BackendKind::serial);
  for (const auto& [kind, threads] : {std::pair{aco::BackendKind::omp, std::size_t{1}},
                                      std::pair{aco::BackendKind::omp, std::size_t{2}},
                                      std::pair{aco::BackendKind::tbb, std::size_t{2}},
                                      std::pair{aco::BackendKind::automatic, std::size_t{2}}}) {
    SCOPED_TRACE(std::string(aco::to_string(kind)) + std::to_string(threads));
    s.backend = kind;
    s.threads = threads;
    const aco::RunResult r = solve(problem, s, t);
    EXPECT_EQ(r.best.path, reference.best.path);
    EXPECT_EQ(r.best.cost, reference.best.cost);
    EXPECT_EQ(r.best_iteration, reference.best_iteration);
    EXPECT_EQ(r.settings.threads, threads);
    EXPECT_EQ(r.settings.backend, aco::resolve(kind, threads));
  }
}

TEST(Solver, SerialBackendOnTwoThreadsIsRefused) {
  SolverSettings s;
  s.backend = aco::BackendKind::serial;
  s.threads = 2;
  EXPECT_THROW(solve(instance_problem("eil51"), s, {.max_iterations = 1}), std::invalid_argument);
}

TEST(Solver, ResultRecordsTheSettingsThatRan) {
  SolverSettings s;  // MMAS + 3-opt with every default
  const aco::RunResult r = solve(instance_problem("eil51"), s, {.max_iterations = 2});
  EXPECT_EQ(r.settings.variant, aco::Variant::mmas);
  EXPECT_EQ(r.settings.colony.ants, 25U);
  EXPECT_DOUBLE_EQ(r.settings.rho, 0.2);
  EXPECT_TRUE(r.settings.local_search);
  EXPECT_EQ(r.settings.backend, aco::BackendKind::serial);
  EXPECT_EQ(r.settings.threads, 1U);
}

INSTANTIATE_TEST_SUITE_P(
    Tsp, Determinism,
    ::testing::Values(Configuration{aco::Variant::mmas, LocalSearchKind::three_opt},
                      Configuration{aco::Variant::mmas, LocalSearchKind::three_opt, 0},
                      Configuration{aco::Variant::acs, LocalSearchKind::two_half_opt},
                      Configuration{aco::Variant::hybrid, LocalSearchKind::two_opt},
                      Configuration{aco::Variant::ant_system, LocalSearchKind::none}),
    [](const auto& param_info) {
      std::string ls(to_string(param_info.param.local_search));
      std::replace(ls.begin(), ls.end(), '.', '_');
      return std::string(aco::to_string(param_info.param.variant)) + "_" + ls +
             (param_info.param.two_level_from == 0 ? "_two_level" : "");
    });

TEST(Solver, MmasRestartsWithLocalSearch) {
  // eil51 is solved within a few iterations; the trails then converge on the best tour and
  // MMAS must re-initialise them (ACOTSP's scheme: restart-best older than 250 iterations and
  // a branching factor of 2, checked every 100 iterations).
  const TspProblem& problem = instance_problem("eil51");
  aco::Colony<TspProblem, aco::RandomProportional, aco::MaxMinUpdate, TourLocalSearch> colony(
      problem, {.ants = 10, .seed = 5}, {}, aco::MaxMinUpdate({.rho = 0.2}), TourLocalSearch());
  for (int it = 0; it < 400; ++it) colony.step();
  EXPECT_EQ(colony.best().cost, 426.0);
  EXPECT_GT(colony.update().restarts(), 0U);
}

// Without local search the colony has one ant per city, each with a tour and visited marks of
// 5 bytes a city: a million cities would need 5 TB, refused up front by `antslam tsp`.
TEST(Solver, ColonyMemoryGrowsWithAntsTimesCities) {
  SolverSettings s;
  s.local_search.kind = LocalSearchKind::none;
  EXPECT_EQ(resolved_ants(std::size_t{1000000}, s), 1000000U);
  EXPECT_DOUBLE_EQ(colony_memory_bytes(1000000, resolved_ants(std::size_t{1000000}, s)), 5e12);
  s.local_search.kind = LocalSearchKind::three_opt;
  EXPECT_DOUBLE_EQ(colony_memory_bytes(1000000, resolved_ants(std::size_t{1000000}, s)), 5e6 * 25);
}

TEST(Solver, ResolvesTheTspDefaults) {
  const TspProblem& problem = instance_problem("eil51");
  SolverSettings s;
  s.local_search.kind = LocalSearchKind::none;
  EXPECT_EQ(resolved_ants(problem, s), 51U);  // MMAS without local search: n ants
  EXPECT_DOUBLE_EQ(resolved_rho(s), 0.02);
  s.local_search.kind = LocalSearchKind::three_opt;
  EXPECT_EQ(resolved_ants(problem, s), 25U);
  EXPECT_DOUBLE_EQ(resolved_rho(s), 0.2);
  s.aco.ants = 7;
  s.aco.rho = 0.3;
  EXPECT_EQ(resolved_ants(problem, s), 7U);
  EXPECT_DOUBLE_EQ(resolved_rho(s), 0.3);
  s.aco.variant = aco::Variant::hybrid;
  EXPECT_DOUBLE_EQ(resolved_parameters(problem, s).hybrid_deposit,
                   nearest_neighbour_length(problem));
  s.hybrid_deposit = 5.0;
  EXPECT_DOUBLE_EQ(resolved_parameters(problem, s).hybrid_deposit, 5.0);
}

TEST(Solver, FocusedConstructionIsMaxMinsDefault) {
  const TspProblem& problem = instance_problem("eil51");
  SolverSettings s;
  EXPECT_EQ(resolved_parameters(problem, s).focused.min_new_edges, 8U);
  s.aco.variant = aco::Variant::acs;
  EXPECT_EQ(resolved_parameters(problem, s).focused.min_new_edges, 0U);
  s.focused_edges = 5;
  EXPECT_EQ(resolved_parameters(problem, s).focused.min_new_edges, 5U);
  s.aco.variant = aco::Variant::mmas;
  s.focused_edges = 0;
  EXPECT_EQ(resolved_parameters(problem, s).focused.min_new_edges, 0U);
  const aco::RunResult r = solve(problem, s, {.max_iterations = 3});
  EXPECT_EQ(r.settings.colony.focused.min_new_edges, 0U);
}

TEST(Solver, NearestNeighbourLengthOfAHandMadeInstance) {
  // A 3 x 2 grid of unit squares (scaled by 10): from city 0 the greedy tour walks the
  // perimeter, 60.
  const std::vector<Point> points = {{0, 0}, {10, 0}, {20, 0}, {20, 10}, {10, 10}, {0, 10}};
  const TspProblem problem(Instance("grid", EdgeWeightType::euc_2d, points));
  EXPECT_EQ(nearest_neighbour_length(problem), 60.0);
}

}  // namespace
}  // namespace antslam::tsp
