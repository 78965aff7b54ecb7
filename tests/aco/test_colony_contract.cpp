// Contract of the colony for every variant x backend x thread count, on both problem families:
// feasible paths, costs equal to a recomputation, pheromone within the variant's bounds, and a
// result (best cost, best path, final pheromone) bit-identical to the serial run.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "aco/backend_omp.hpp"
#include "aco/backend_tbb.hpp"
#include "aco/synthetic_layered.hpp"
#include "aco/variants.hpp"
#include "test_problems.hpp"

namespace antslam::aco {
namespace {

struct BackendSpec {
  std::string kind;
  std::size_t threads;
};

AnyBackend make_backend(const BackendSpec& spec) {
  if (spec.kind == "omp") return OmpBackend(spec.threads);
  if (spec.kind == "tbb") return TbbBackend(spec.threads);
  return SerialBackend{};
}

struct Outcome {
  Solution best;
  std::vector<double> trail;
};

template <class Problem>
bool feasible(const Problem& problem, std::span<const std::uint32_t> path) {
  if constexpr (PermutationProblem<Problem>) {
    return testing::is_permutation_of_n(path, problem.size());
  } else {
    if (path.size() != problem.layer_count()) return false;
    for (std::size_t l = 0; l < path.size(); ++l)
      if (path[l] >= problem.option_count(l)) return false;
    return true;
  }
}

template <class Problem>
Outcome run_checked(const Problem& problem, Variant variant, std::size_t iterations,
                    const BackendSpec& spec) {
  Parameters p;
  p.variant = variant;
  p.ants = 12;
  p.seed = 2024;
  constexpr bool permutation = PermutationProblem<Problem>;
  std::size_t decisions = 0;
  if constexpr (permutation) {
    decisions = problem.size();
  } else {
    decisions = problem.layer_count();
  }
  const ColonySettings settings = colony_settings(p, decisions, permutation, false);
  return with_variant_policies(p, default_rho(variant, false), [&](auto rule, auto update) {
    Colony<Problem, decltype(rule), decltype(update), NoLocalSearch, AnyBackend> colony(
        problem, settings, rule, update, {}, make_backend(spec));
    for (std::size_t it = 0; it < iterations; ++it) {
      colony.step();
      for (const Solution& ant : colony.ants()) {
        EXPECT_TRUE(feasible(problem, ant.path));
        EXPECT_EQ(ant.cost, problem.cost(ant.path));
        EXPECT_LE(colony.best().cost, ant.cost);
      }
      const auto& trail = colony.trail();
      EXPECT_GE(trail.min_value(), 0.0);
      if constexpr (requires { colony.update().tau_min(); }) {  // MAX-MIN bounds
        EXPECT_GE(trail.min_value(), colony.update().tau_min());
        EXPECT_LE(trail.max_value(), colony.update().tau_max());
      }
      if constexpr (requires { colony.update().tau_max; }) {  // hybrid cap
        EXPECT_LE(trail.max_value(), colony.update().tau_max);
      }
    }
    EXPECT_EQ(colony.best().cost, problem.cost(colony.best().path));
    const auto values = colony.trail().values();
    return Outcome{colony.best(), std::vector<double>(values.begin(), values.end())};
  });
}

class ColonyContract : public ::testing::TestWithParam<std::tuple<Variant, BackendSpec>> {};

TEST_P(ColonyContract, LayeredProblemDeterministicAndValid) {
  const auto [variant, spec] = GetParam();
  const SyntheticLayeredProblem problem(8, 6, 17);
  const Outcome reference = run_checked(problem, variant, 40, {"serial", 1});
  const Outcome outcome = run_checked(problem, variant, 40, spec);
  EXPECT_EQ(outcome.best.cost, reference.best.cost);
  EXPECT_EQ(outcome.best.path, reference.best.path);
  EXPECT_EQ(outcome.trail, reference.trail);
}

TEST_P(ColonyContract, PermutationProblemDeterministicAndValid) {
  const auto [variant, spec] = GetParam();
  const testing::EuclideanTsp problem(30, 8, 5);
  const Outcome reference = run_checked(problem, variant, 25, {"serial", 1});
  const Outcome outcome = run_checked(problem, variant, 25, spec);
  EXPECT_EQ(outcome.best.cost, reference.best.cost);
  EXPECT_EQ(outcome.best.path, reference.best.path);
  EXPECT_EQ(outcome.trail, reference.trail);
}

const std::vector<BackendSpec> kBackends{{"serial", 1}, {"omp", 1}, {"omp", 2}, {"omp", 3},
                                         {"omp", 4},    {"omp", 8}, {"tbb", 1}, {"tbb", 2},
                                         {"tbb", 3},    {"tbb", 4}, {"tbb", 8}};

INSTANTIATE_TEST_SUITE_P(AllVariantsAllBackends, ColonyContract,
                         ::testing::Combine(::testing::Values(Variant::ant_system, Variant::elitist,
                                                              Variant::rank_based, Variant::acs,
                                                              Variant::mmas, Variant::hybrid),
                                            ::testing::ValuesIn(kBackends)),
                         [](const auto& param_info) {
                           const auto& spec = std::get<1>(param_info.param);
                           return std::string(to_string(std::get<0>(param_info.param))) + "_" +
                                  spec.kind + std::to_string(spec.threads);
                         });

}  // namespace
}  // namespace antslam::aco
