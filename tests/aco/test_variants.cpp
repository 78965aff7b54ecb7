// Variant-specific rules and the run loop's termination criteria.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <span>
#include <stop_token>
#include <string>
#include <utility>
#include <vector>

#include "antslam/aco/subset_trail.hpp"
#include "antslam/aco/synthetic_layered.hpp"
#include "antslam/aco/variants.hpp"
#include "test_problems.hpp"

namespace antslam::aco {
namespace {

double brute_force_tour(const testing::EuclideanTsp& tsp) {
  std::vector<std::uint32_t> tour(tsp.size());
  std::iota(tour.begin(), tour.end(), 0U);
  double best = std::numeric_limits<double>::infinity();
  do {  // city 0 fixed first
    best = std::min(best, tsp.cost(tour));
  } while (std::next_permutation(tour.begin() + 1, tour.end()));
  return best;
}

class EveryVariant : public ::testing::TestWithParam<Variant> {};

TEST_P(EveryVariant, FindsTheOptimumOfASmallTsp) {
  const testing::EuclideanTsp tsp(9, 8, 77);
  const double optimum = brute_force_tour(tsp);
  Parameters p;
  p.variant = GetParam();
  p.ants = 10;
  p.seed = 1;
  const RunResult result = solve(tsp, p, {.max_iterations = 300, .target_cost = optimum});
  EXPECT_EQ(result.best.cost, optimum);
  EXPECT_EQ(result.reason, StopReason::target);
}

INSTANTIATE_TEST_SUITE_P(All, EveryVariant, ::testing::ValuesIn(all_variants()),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

// Without a heuristic, Ant System and ACS stagnate early on layered problems (AS: rho = 0.5;
// ACS: q0 = 0.9 greedy), which is why the paper moved to its hybrid; MAX-MIN and the hybrid must
// find the optimum.
class LayeredVariant : public ::testing::TestWithParam<Variant> {};

TEST_P(LayeredVariant, FindsTheOptimumOfASmallLayeredProblem) {
  const SyntheticLayeredProblem problem(4, 5, 8);
  const Solution optimum = testing::exhaustive_optimum(problem);
  Parameters p;
  p.variant = GetParam();
  p.seed = 2;
  const RunResult result = solve(problem, p, {.max_iterations = 400, .target_cost = optimum.cost});
  EXPECT_EQ(result.best.cost, optimum.cost);
  EXPECT_EQ(result.best.path, optimum.path);
}

INSTANTIATE_TEST_SUITE_P(Robust, LayeredVariant, ::testing::Values(Variant::mmas, Variant::hybrid),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

TEST(Variants, NamesRoundTrip) {
  for (Variant v : {Variant::ant_system, Variant::elitist, Variant::rank_based, Variant::acs,
                    Variant::mmas, Variant::hybrid})
    EXPECT_EQ(parse_variant(to_string(v)), v);
  EXPECT_FALSE(parse_variant("aco").has_value());
}

TEST(Mmas, BoundsFollowTheBestCost) {
  const testing::EuclideanTsp tsp(30, 8, 3);
  Colony<testing::EuclideanTsp, RandomProportional, MaxMinUpdate> colony(
      tsp, {.ants = 10, .seed = 1}, {}, MaxMinUpdate({.rho = 0.02}));
  for (int it = 0; it < 30; ++it) colony.step();
  const double best = colony.best().cost;
  EXPECT_DOUBLE_EQ(colony.update().tau_max(), 1.0 / (0.02 * best));
  const double p_dec = std::pow(0.05, 1.0 / 30.0);
  const double avg = (8.0 + 1.0) / 2.0;
  EXPECT_DOUBLE_EQ(colony.update().tau_min(),
                   colony.update().tau_max() * (1.0 - p_dec) / ((avg - 1.0) * p_dec));
}

TEST(Mmas, ReinitialisesTrailsOnStagnation) {
  const SyntheticLayeredProblem problem(5, 4, 6);
  const MaxMinUpdate rule({.rho = 0.3, .check_every = 10, .restart_after = 20});
  Colony<SyntheticLayeredProblem, RandomProportional, MaxMinUpdate> colony(
      problem, {.ants = 10, .seed = 1}, {}, rule);
  for (int it = 0; it < 300; ++it) colony.step();
  EXPECT_GT(colony.update().restarts(), 0U);
}

TEST(Mmas, ReinitialisesTrailsWhenTheRestartBestIsKIterationsOld) {
  // One unchanging best {0, 1} of cost 10, found at iteration 1: with rho 0.2 and local search
  // tau_max = 1 / (0.2 * 10) = 0.5, elements 2 and 3 evaporate, and at iteration 1 + 3 the
  // restart-best is 3 iterations old: every trail is tau_max again.
  const Solution best{{0, 1}, 10.0};
  const auto run = [&](std::uint64_t restart_stagnant, std::uint64_t iterations) {
    MaxMinUpdate update({.rho = 0.2, .restart_stagnant = restart_stagnant});
    SubsetTrail trail(4);
    update.initialize(trail, {.reference_cost = 10.0, .decisions = 4, .local_search = true});
    for (std::uint64_t it = 1; it <= iterations; ++it)
      update.apply(trail, {.ants = {},
                           .ranking = {},
                           .iteration_best = best,
                           .global_best = best,
                           .iteration = it});
    return std::pair{trail, update.restarts()};
  };
  const auto [before, none] = run(3, 3);
  EXPECT_EQ(none, 0U);
  EXPECT_DOUBLE_EQ(before.at(0), 0.5);  // deposited every iteration, clamped at tau_max
  EXPECT_LT(before.at(2), 0.5 * 0.8 * 0.8 + 1e-12);
  const auto [after, one] = run(3, 4);
  EXPECT_EQ(one, 1U);
  for (std::size_t e = 0; e < 4; ++e) EXPECT_DOUBLE_EQ(after.at(e), 0.5) << e;
  EXPECT_EQ(run(3, 7).second, 1U);   // the next restart-best is found at 5 ...
  EXPECT_EQ(run(3, 8).second, 2U);   // ... and is 3 iterations old at 8
  EXPECT_EQ(run(0, 40).second, 0U);  // ACOTSP's test: not before iteration 250
}

TEST(Acs, LocalUpdateErodesUsedEdgesTowardsTau0) {
  const testing::EuclideanTsp tsp(20, 6, 4);
  Colony<testing::EuclideanTsp, PseudoRandomProportional, AcsUpdate> colony(
      tsp, {.ants = 10, .seed = 1}, PseudoRandomProportional{0.9},
      AcsUpdate{.rho = 0.1, .xi = 0.1});
  const double tau0 = colony.update().tau0;
  colony.step();
  // The best-so-far edges got the global deposit; every other value stays between tau0 and it.
  for (double t : colony.trail().values()) EXPECT_GE(t, tau0 * (1.0 - 1e-12));
  EXPECT_GT(colony.trail().max_value(), tau0);
}

TEST(Termination, StopsAtTheIterationBudget) {
  const SyntheticLayeredProblem problem(5, 4, 1);
  Parameters p;
  p.variant = Variant::hybrid;
  int calls = 0;
  double last_best = std::numeric_limits<double>::infinity();
  const RunResult r = solve(problem, p, {.max_iterations = 37}, AnyBackend{}, NoLocalSearch{},
                            [&](const IterationReport& report) {
                              ++calls;
                              EXPECT_EQ(report.iteration, static_cast<std::uint64_t>(calls));
                              EXPECT_LE(report.global_best, last_best);
                              EXPECT_LE(report.global_best, report.iteration_best);
                              last_best = report.global_best;
                            });
  EXPECT_EQ(r.iterations, 37U);
  EXPECT_EQ(calls, 37);
  EXPECT_EQ(r.reason, StopReason::iterations);
  EXPECT_LE(r.best_iteration, 37U);
}

TEST(Termination, StopsOnStagnation) {
  const SyntheticLayeredProblem problem(3, 3, 1);
  Parameters p;
  p.variant = Variant::hybrid;
  const RunResult r = solve(problem, p, {.max_iterations = 100000, .stagnation_iterations = 25});
  EXPECT_EQ(r.reason, StopReason::stagnation);
  EXPECT_EQ(r.iterations - r.best_iteration, 25U);
}

TEST(Termination, StopsOnTheTimeBudget) {
  const SyntheticLayeredProblem problem(6, 6, 1);
  Parameters p;
  p.variant = Variant::hybrid;
  const RunResult r = solve(problem, p, {.time_limit_s = 0.05});
  EXPECT_EQ(r.reason, StopReason::time);
  EXPECT_GE(r.elapsed_s, 0.05);
  EXPECT_LE(r.time_to_best_s, r.elapsed_s);
}

// A stop request (a user's Ctrl-C) ends the run after the iteration in which it came, and
// expires the token that local searches poll; the run up to there is the uninterrupted run's.
TEST(Termination, AStopRequestEndsTheRunAfterItsIteration) {
  const SyntheticLayeredProblem problem(6, 5, 2);
  Parameters p;
  p.variant = Variant::mmas;
  std::stop_source source;
  std::vector<double> interrupted_bests;
  const RunResult r = solve(problem, p, {.max_iterations = 1000, .stop = source.get_token()},
                            AnyBackend{}, NoLocalSearch{}, [&](const IterationReport& report) {
                              interrupted_bests.push_back(report.global_best);
                              if (report.iteration == 7) source.request_stop();
                            });
  EXPECT_EQ(r.reason, StopReason::interrupted);
  EXPECT_EQ(r.iterations, 7U);
  std::vector<double> bests;
  solve(problem, p, {.max_iterations = 7}, AnyBackend{}, NoLocalSearch{},
        [&](const IterationReport& report) { bests.push_back(report.global_best); });
  EXPECT_EQ(interrupted_bests, bests);
  constexpr auto kNever = StopToken::Clock::time_point::max();
  constexpr double kNoCpuLimit = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(StopToken(kNever, kNoCpuLimit, source.get_token()).expired());
  EXPECT_FALSE(StopToken(kNever, kNoCpuLimit, std::stop_source().get_token()).expired());
}

// Nonsense parameters are refused with one line naming the field, before any ant runs.
TEST(Parameters, NonsenseIsRefusedByName) {
  const SyntheticLayeredProblem problem(3, 3, 1);
  const auto error_of = [&](auto change) {
    Parameters p;
    change(p);
    try {
      solve(problem, p, {.max_iterations = 1});
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error_of([](Parameters& p) { p.rho = 1.5; }),
            "aco: rho must be in [0, 1] (0: the variant's default)");
  EXPECT_EQ(error_of([](Parameters& p) { p.alpha = std::nan(""); }),
            "aco: alpha must be a finite number >= 0");
  EXPECT_EQ(error_of([](Parameters& p) { p.p_best = 1.0; }), "aco: p_best must be in (0, 1)");
  EXPECT_EQ(error_of([](Parameters& p) { p.tau_init = 2.0 * p.tau_max; }),
            "aco: need 0 < tau_init <= tau_max, both finite");
  EXPECT_EQ(error_of([](Parameters&) {}), "no error");
}

/// A layered problem whose cost is `value` whatever the choice: 2 layers of 2 options.
struct ConstantCost {
  double value;
  std::size_t layer_count() const { return 2; }
  std::size_t option_count(std::size_t) const { return 2; }
  double cost(std::span<const std::uint32_t>) const { return value; }
};

TEST(Costs, ANegativeOrNanCostIsRefusedByEveryVariantAndZeroOrInfinityIsNot) {
  const std::string advice =
      "; a problem's costs must be numbers >= 0 (to maximise a value v, minimise e.g. bound - v "
      "or 1 / (1 + v))";
  for (const VariantInfo& info : kVariants) {
    Parameters p;
    p.variant = info.variant;
    const auto error_of = [&](double value) {
      try {
        solve(ConstantCost{value}, p, {.max_iterations = 3});
      } catch (const std::invalid_argument& e) {
        return std::string(e.what());
      }
      return std::string("no error");
    };
    EXPECT_EQ(error_of(-54.0), "aco: a solution's cost is -54" + advice) << info.name;
    EXPECT_EQ(error_of(std::nan("")), "aco: a solution's cost is nan" + advice);
    EXPECT_EQ(error_of(0.0), "no error");
    EXPECT_EQ(error_of(std::numeric_limits<double>::infinity()), "no error");
  }
}

TEST(Termination, RejectsAnUnboundedRunAndNonsenseBudgets) {
  const SyntheticLayeredProblem problem(3, 3, 1);
  const auto error_of = [&](Termination t) -> std::string {
    try {
      solve(problem, Parameters{}, t);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(error_of({}), "termination: set iterations, a time budget, a target or stagnation");
  const std::string time = "termination: the time limit must be a finite number of seconds >= 0";
  const std::string cpu = "termination: the CPU-time limit must be a finite number of seconds >= 0";
  for (const double bad : {-1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    EXPECT_EQ(error_of({.max_iterations = 2, .time_limit_s = bad}), time + " (0: none)");
    EXPECT_EQ(error_of({.max_iterations = 2, .cpu_time_limit_s = bad}), cpu + " (0: none)");
  }
  EXPECT_EQ(error_of({.max_iterations = 2, .target_cost = std::nan("")}),
            "termination: the target is NaN");
  EXPECT_EQ(error_of({.max_iterations = 2, .time_limit_s = 0.0}), "no error");
}

}  // namespace
}  // namespace antslam::aco
