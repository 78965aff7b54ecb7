// Budgets inside one iteration of a large instance: once the run's stop token has expired, the
// construction finishes the tour it is building at its next poll (every 1024 cities) by
// appending the unvisited cities in index order, the ants not yet begun are not built, and the
// run ends after that iteration with a valid tour. The tests count work done (cities chosen by
// the rule, ants built, iterations), never time.

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "antslam/aco/variants.hpp"
#include "antslam/tsp/solver.hpp"
#include "tsp_test_support.hpp"

namespace antslam::tsp {
namespace {

constexpr std::size_t kCities = 5000;
constexpr std::size_t kPoll = 1024;  // cities the construction places between polls

const TspProblem& problem() {
  static const TspProblem p(testing::random_instance(kCities, 3, EdgeWeightType::euc_2d),
                            {.matrix_limit = 0});
  return p;
}

aco::StopToken expired() {
  return aco::StopToken(aco::StopToken::Clock::now() - std::chrono::seconds(1),
                        std::numeric_limits<double>::infinity());
}

/// Length of the tour's longest suffix in increasing city order: the cities appended once the
/// construction stopped (a tour the rule built to the end has a suffix of a few cities).
std::size_t ascending_tail(std::span<const std::uint32_t> tour) {
  std::size_t k = 1;
  while (k < tour.size() && tour[tour.size() - k - 1] < tour[tour.size() - k]) ++k;
  return k;
}

aco::Parameters colony_of(aco::Variant variant) {
  return {.variant = variant, .ants = 10, .seed = 4};
}

std::vector<double> trail_of(const auto& colony) {
  const auto values = colony.trail().values();
  return {values.begin(), values.end()};
}

// Without the stop token the ant would choose all 5000 cities with the rule; with it, at most
// the first 1024. Ants 1..9 are not built: they repeat ant 0's tour. The run ends after such an
// iteration, so the trail is not updated (every ant's deposit on a million-city tour takes
// seconds).
TEST(Budget, AnExpiredTokenStopsTheConstructionAtItsFirstPoll) {
  aco::with_colony(problem(), colony_of(aco::Variant::mmas), aco::SerialBackend{},
                   aco::NoLocalSearch{}, [](auto& colony) {
                     const std::vector<double> initial = trail_of(colony);
                     colony.step(expired());
                     EXPECT_EQ(trail_of(colony), initial);
                     const auto ants = colony.ants();
                     ASSERT_TRUE(testing::is_permutation_of_n(ants[0].path, kCities));
                     EXPECT_GE(ascending_tail(ants[0].path), kCities - kPoll);
                     for (std::size_t a = 1; a < ants.size(); ++a)
                       EXPECT_EQ(ants[a].path, ants[0].path) << "ant " << a << " was built";
                     EXPECT_EQ(colony.best().cost, problem().cost(ants[0].path));
                   });
  // The same colony without a stop builds every tour with the rule.
  aco::with_colony(problem(), colony_of(aco::Variant::mmas), aco::SerialBackend{},
                   aco::NoLocalSearch{}, [](auto& colony) {
                     const std::vector<double> initial = trail_of(colony);
                     colony.step();
                     for (const aco::Solution& ant : colony.ants())
                       EXPECT_LT(ascending_tail(ant.path), kCities - kPoll);
                     EXPECT_NE(trail_of(colony), initial);
                   });
}

// Ant Colony System moves its ants in step (Dorigo & Gambardella 1997): every ant stops at the
// same poll.
TEST(Budget, AnExpiredTokenStopsTheSynchronousConstructionOfEveryAnt) {
  aco::with_colony(problem(), colony_of(aco::Variant::acs), aco::SerialBackend{},
                   aco::NoLocalSearch{}, [](auto& colony) {
                     colony.step(expired());
                     for (const aco::Solution& ant : colony.ants()) {
                       ASSERT_TRUE(testing::is_permutation_of_n(ant.path, kCities));
                       EXPECT_GE(ascending_tail(ant.path), kCities - kPoll);
                       EXPECT_EQ(ant.cost, problem().cost(ant.path));
                     }
                   });
}

// A run whose budget is spent before its first iteration ends -- wall clock or CPU time --
// after that iteration, with a valid tour that the local search only shortened.
TEST(Budget, ASpentBudgetEndsTheRunAfterOneIterationWithAValidTour) {
  for (const aco::Variant variant : {aco::Variant::mmas, aco::Variant::acs, aco::Variant::hybrid})
    for (const bool cpu : {false, true}) {
      SolverSettings s;
      s.aco.variant = variant;
      s.aco.ants = 10;
      aco::Termination budget;
      (cpu ? budget.cpu_time_limit_s : budget.time_limit_s) = 1e-9;
      const aco::RunResult r = solve(problem(), s, budget);
      EXPECT_EQ(r.iterations, 1U) << aco::to_string(variant);
      EXPECT_EQ(r.reason, cpu ? aco::StopReason::cpu_time : aco::StopReason::time);
      ASSERT_TRUE(testing::is_permutation_of_n(r.best.path, kCities));
      EXPECT_EQ(r.best.cost, problem().cost(r.best.path));
    }
}

}  // namespace
}  // namespace antslam::tsp
