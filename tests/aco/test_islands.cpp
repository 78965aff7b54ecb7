// The island model: a colony receiving an immigrant, and the driver that runs K colonies in
// lockstep and exchanges their best solutions.

#include <gtest/gtest.h>

#include <algorithm>
#include <barrier>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <numbers>
#include <set>
#include <stdexcept>
#include <stop_token>
#include <thread>
#include <utility>
#include <vector>

#include "antslam/aco/backend_factory.hpp"
#include "antslam/aco/colony.hpp"
#include "antslam/aco/islands.hpp"
#include "antslam/aco/rules.hpp"
#include "antslam/aco/update_mmas.hpp"
#include "antslam/aco/variants.hpp"
#include "test_problems.hpp"

namespace antslam::aco {
namespace {

using testing::EuclideanTsp;
using MmasColony = Colony<EuclideanTsp, RandomProportional, MaxMinUpdate>;

/// n cities on a circle of radius 1000: the tour around it is the optimum.
EuclideanTsp circle(std::size_t n, std::size_t k) {
  std::pair<std::vector<double>, std::vector<double>> xy;
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    xy.first.push_back(1000.0 + 1000.0 * std::cos(angle));
    xy.second.push_back(1000.0 + 1000.0 * std::sin(angle));
  }
  return EuclideanTsp(std::move(xy), k);
}

Solution around(const EuclideanTsp& problem) {
  Solution s;
  for (std::uint32_t i = 0; i < problem.size(); ++i) s.path.push_back(i);
  s.cost = problem.cost(s.path);
  return s;
}

/// One ant, no heuristic: the colony wanders and does not find the circle in 25 iterations.
ColonySettings wandering(std::uint64_t seed) {
  ColonySettings s;
  s.ants = 1;
  s.beta = 0.0;
  s.seed = seed;
  return s;
}

std::vector<double> trail_values(const EdgeTrail& trail) {
  std::vector<double> values;
  for (std::uint32_t i = 0; i < trail.node_count(); ++i)
    for (double t : trail.row(i)) values.push_back(t);
  return values;
}

TEST(Receive, BetterImmigrantIsBestSoFarAndMmasDepositsIt) {
  const EuclideanTsp problem = circle(16, 6);
  const MaxMinSettings mmas{.rho = 0.1, .p_best = 0.05, .reinitialize = false};
  MmasColony colony(problem, wandering(3), {}, MaxMinUpdate(mmas));
  for (int t = 0; t < 24; ++t) colony.step();
  const Solution immigrant = around(problem);
  ASSERT_GT(colony.best().cost, immigrant.cost);
  ASSERT_TRUE(colony.receive(immigrant));
  EXPECT_EQ(colony.best().cost, immigrant.cost);
  EXPECT_EQ(colony.best().path, immigrant.path);

  // Iteration 25 is a scheduled restart-best deposit of MMAS without local search (every 25th):
  // tau <- clamp((1 - rho) tau + [edge on the immigrant] / L_imm, tau_min, tau_max), with the
  // limits from L_imm: tau_max = 1 / (rho L_imm), tau_min = tau_max (1 - p_dec) /
  // ((avg - 1) p_dec), p_dec = p_best^(1/n), avg = (k + 1) / 2 (Stuetzle & Hoos 2000, eq. 11).
  const std::vector<double> before = trail_values(colony.trail());
  colony.step();
  ASSERT_GT(colony.ants()[0].cost, immigrant.cost);  // the ant did not find the circle itself
  const double tau_max = 1.0 / (0.1 * immigrant.cost);
  const double p_dec = std::pow(0.05, 1.0 / 16.0);
  const double tau_min = tau_max * (1.0 - p_dec) / ((3.5 - 1.0) * p_dec);
  EXPECT_DOUBLE_EQ(colony.update().tau_max(), tau_max);
  EXPECT_DOUBLE_EQ(colony.update().tau_min(), tau_min);
  const EdgeTrail& trail = colony.trail();
  std::size_t index = 0;
  std::size_t deposited = 0;
  for (std::uint32_t i = 0; i < 16; ++i)
    for (std::uint32_t j : trail.neighbours(i)) {
      const bool on_circle = (i + 1) % 16 == j || (j + 1) % 16 == i;
      deposited += on_circle ? 1 : 0;
      const double expected = std::clamp(
          0.9 * before[index] + (on_circle ? 1.0 / immigrant.cost : 0.0), tau_min, tau_max);
      EXPECT_NEAR(trail.edge(i, j), expected, 1e-12 * tau_max) << i << "-" << j;
      ++index;
    }
  EXPECT_EQ(deposited, 32U);  // both copies of the 16 circle edges
}

TEST(Receive, WorseImmigrantChangesNothing) {
  const EuclideanTsp problem(30, 8, 5);
  MmasColony colony(problem, wandering(7), {}, MaxMinUpdate());
  MmasColony twin(problem, wandering(7), {}, MaxMinUpdate());
  for (int t = 0; t < 10; ++t) {
    colony.step();
    twin.step();
  }
  Solution worse = colony.best();
  std::reverse(worse.path.begin() + 1, worse.path.begin() + 15);
  worse.cost = problem.cost(worse.path);
  ASSERT_GE(worse.cost, colony.best().cost);
  const Solution equal = colony.best();
  EXPECT_FALSE(colony.receive(worse));
  EXPECT_FALSE(colony.receive(equal));
  for (int t = 0; t < 30; ++t) {
    colony.step();
    twin.step();
  }
  EXPECT_EQ(colony.best().path, twin.best().path);
  EXPECT_EQ(trail_values(colony.trail()), trail_values(twin.trail()));
}

TEST(Islands, ImmigrantSourceFollowsTheTopology) {
  std::vector<Offer> offers(4);
  const double costs[] = {5.0, 3.0, 3.0, 4.0};
  for (std::size_t c = 0; c < 4; ++c) offers[c].best = costs[c];
  EXPECT_EQ(immigrant_source(0, offers, Topology::ring), 3U);
  EXPECT_EQ(immigrant_source(2, offers, Topology::ring), 1U);
  EXPECT_EQ(immigrant_source(0, offers, Topology::full), 1U);  // tie 1/2: the lower
  EXPECT_EQ(immigrant_source(1, offers, Topology::full), 2U);
  EXPECT_EQ(immigrant_source(3, offers, Topology::full), 1U);
}

TEST(Islands, ColonyZeroKeepsTheSeedTheOthersMixIt) {
  EXPECT_EQ(colony_seed(42, 0), 42U);
  std::set<std::uint64_t> seeds;
  for (std::size_t c = 0; c < 8; ++c) seeds.insert(colony_seed(42, c));
  EXPECT_EQ(seeds.size(), 8U);
  EXPECT_NE(colony_seed(42, 1), colony_seed(43, 1));
}

Parameters mmas_parameters(std::uint64_t seed) {
  Parameters p;
  p.variant = Variant::mmas;
  p.ants = 5;
  p.seed = seed;
  return p;
}

IslandResult islands(const EuclideanTsp& problem, const Parameters& p, IslandSettings s,
                     std::uint64_t iterations, BackendKind backend = BackendKind::serial,
                     std::size_t threads = 1, const IslandObserver& observer = {}) {
  return solve_islands(
      problem, p, Termination{.max_iterations = iterations},
      [&] { return make_backend(backend, threads); }, NoLocalSearch{}, s, in_process_exchange,
      observer);
}

TEST(Islands, OneColonyIsThePlainRun) {
  const EuclideanTsp problem(40, 8, 11);
  for (Variant v : {Variant::mmas, Variant::acs, Variant::hybrid}) {
    Parameters p = mmas_parameters(9);
    p.variant = v;
    const RunResult plain = solve(problem, p, Termination{.max_iterations = 60});
    const IslandResult island = islands(problem, p, {.colonies = 1}, 60);
    EXPECT_EQ(island.run.best.path, plain.best.path) << to_string(v);
    EXPECT_EQ(island.run.best.cost, plain.best.cost);
    EXPECT_EQ(island.run.best_iteration, plain.best_iteration);
    EXPECT_EQ(island.run.iterations, 60U);
    EXPECT_EQ(island.run.reason, StopReason::iterations);
    EXPECT_EQ(island.exchanges, 0U);
  }
}

TEST(Islands, RingPassesEachBestToTheNextColony) {
  const EuclideanTsp problem(60, 8, 13);
  std::uint64_t checked = 0;
  const auto observer = [&](const IslandReport& r) {
    ASSERT_TRUE(r.exchanged);  // E = 1: every boundary but the last
    for (std::size_t c = 0; c < 4; ++c) {
      EXPECT_LE(r.local[c], r.offered[(c + 3) % 4]) << "iteration " << r.run.iteration;
      EXPECT_LE(r.local[c], r.offered[c]);
    }
    ++checked;
  };
  const IslandResult result =
      islands(problem, mmas_parameters(4), {.colonies = 4, .exchange_every = 1}, 30,
              BackendKind::serial, 1, [&](const IslandReport& r) {
                if (r.run.iteration < 30) observer(r);
              });
  EXPECT_EQ(checked, 29U);
  EXPECT_EQ(result.exchanges, 29U);
  EXPECT_GT(result.immigrants, 0U);
  EXPECT_EQ(result.colony_best.size(), 4U);
  EXPECT_EQ(result.run.best.cost,
            *std::min_element(result.colony_best.begin(), result.colony_best.end()));
  EXPECT_EQ(result.run.best.cost, problem.cost(result.run.best.path));
}

TEST(Islands, FullTopologyGivesEveryColonyTheBest) {
  const EuclideanTsp problem(60, 8, 17);
  std::uint64_t exchanges = 0;
  const auto observer = [&](const IslandReport& r) {
    if (!r.exchanged) return;
    ++exchanges;
    const double best = *std::min_element(r.offered.begin(), r.offered.end());
    for (double kept : r.local) EXPECT_EQ(kept, best) << "iteration " << r.run.iteration;
  };
  const IslandResult result = islands(
      problem, mmas_parameters(8), {.colonies = 3, .exchange_every = 5, .topology = Topology::full},
      40, BackendKind::serial, 1, observer);
  EXPECT_EQ(exchanges, 7U);  // at 5, 10, ..., 35 (the run stops at 40)
  EXPECT_EQ(result.exchanges, 7U);
}

TEST(Islands, IdenticalForEveryBackendAndThreadCount) {
  const EuclideanTsp problem(50, 8, 19);
  const IslandSettings s{.colonies = 3, .exchange_every = 4};
  const IslandResult serial = islands(problem, mmas_parameters(2), s, 50);
  for (const auto& [backend, threads] :
       {std::pair{BackendKind::omp, std::size_t{1}}, std::pair{BackendKind::omp, std::size_t{2}},
        std::pair{BackendKind::tbb, std::size_t{2}}}) {
    const IslandResult other = islands(problem, mmas_parameters(2), s, 50, backend, threads);
    EXPECT_EQ(other.run.best.path, serial.run.best.path) << to_string(backend) << threads;
    EXPECT_EQ(other.colony_best, serial.colony_best);
    EXPECT_EQ(other.run.best_iteration, serial.run.best_iteration);
  }
}

/// Processes simulated by threads: each runs its share of the colonies, and the exchange
/// gathers every share through shared slots between two barriers, as an all-gather would. A
/// failure of any share makes every share throw at the same boundary.
class ThreadedExchange {
 public:
  explicit ThreadedExchange(std::size_t processes, std::size_t colonies)
      : sync_(static_cast<std::ptrdiff_t>(processes)), slots_(colonies), failed_(processes) {}

  Exchange for_process(std::size_t process, std::size_t first) {
    return [this, process, first](std::vector<Offer> local, const std::exception_ptr& failure) {
      failed_[process] = failure ? 1 : 0;
      for (std::size_t i = 0; i < local.size(); ++i) slots_[first + i] = local[i];
      sync_.arrive_and_wait();
      std::vector<Offer> all = slots_;
      const bool any_failed = std::count(failed_.begin(), failed_.end(), 1) > 0;
      sync_.arrive_and_wait();
      if (any_failed) throw std::runtime_error("a share failed");
      return all;
    };
  }

 private:
  std::barrier<> sync_;
  std::vector<Offer> slots_;
  std::vector<int> failed_;
};

TEST(Islands, SpreadOverProcessesIsTheSameRun) {
  const EuclideanTsp problem(50, 8, 23);
  const IslandSettings whole{.colonies = 4, .exchange_every = 3};
  const Parameters p = mmas_parameters(6);
  const IslandResult in_one = islands(problem, p, whole, 40);
  for (std::size_t processes : {2U, 4U}) {
    ThreadedExchange exchange(processes, 4);
    std::vector<IslandResult> results(processes);
    std::vector<std::jthread> threads;
    for (std::size_t r = 0; r < processes; ++r)
      threads.emplace_back([&, r] {
        IslandSettings mine = whole;
        mine.local = 4 / processes;
        mine.first = r * mine.local;
        results[r] = solve_islands(
            problem, p, Termination{.max_iterations = 40}, [] { return SerialBackend{}; },
            NoLocalSearch{}, mine, exchange.for_process(r, mine.first));
      });
    threads.clear();
    for (const IslandResult& r : results) {
      EXPECT_EQ(r.run.best.path, in_one.run.best.path) << processes << " processes";
      EXPECT_EQ(r.colony_best, in_one.colony_best);
      EXPECT_EQ(r.best_colony, in_one.best_colony);
      EXPECT_EQ(r.run.best_iteration, in_one.run.best_iteration);
      EXPECT_EQ(r.run.settings.colony.seed, 6U);
    }
  }
}

/// Two processes of two colonies, one each, simulated by threads: share(r, exchange, observer)
/// runs process r's island run. Which shares threw, and the last boundary each observed.
struct SharesEnd {
  std::vector<int> threw{0, 0};
  std::vector<std::uint64_t> last_iteration{0, 0};
};
template <class Share>
SharesEnd run_two_shares(Share share) {
  ThreadedExchange exchange(2, 2);
  SharesEnd end;
  std::vector<std::jthread> threads;
  for (std::size_t r = 0; r < 2; ++r)
    threads.emplace_back([&, r] {
      const IslandObserver observe = [&](const IslandReport& report) {
        end.last_iteration[r] = report.run.iteration;
      };
      try {
        share(r, exchange.for_process(r, r), observe);
      } catch (const std::runtime_error&) {
        end.threw[r] = 1;
      }
    });
  threads.clear();
  return end;
}

TEST(Islands, AFailingShareStopsEveryShareAtTheSameBoundary) {
  const EuclideanTsp problem(30, 8, 29);
  const SharesEnd end =
      run_two_shares([&](std::size_t r, const Exchange& exchange, const IslandObserver& observe) {
        const auto make_colony = [&](std::size_t c) {
          if (c == 1) throw std::runtime_error("colony 1 cannot start");
          return std::make_unique<MmasColony>(problem, wandering(colony_seed(1, c)),
                                              RandomProportional{}, MaxMinUpdate());
        };
        run_islands(make_colony, {.colonies = 2, .first = r, .local = 1},
                    Termination{.max_iterations = 10}, exchange, observe);
      });
  EXPECT_EQ(end.threw, (std::vector<int>{1, 1}));
  EXPECT_EQ(end.last_iteration, (std::vector<std::uint64_t>{0, 0}));
}

TEST(Islands, AFailingObserverStopsEveryShareAtTheNextBoundary) {
  const EuclideanTsp problem(30, 8, 41);
  const SharesEnd end =
      run_two_shares([&](std::size_t r, const Exchange& exchange, const IslandObserver& observe) {
        solve_islands(
            problem, mmas_parameters(2), Termination{.max_iterations = 10},
            [] { return SerialBackend{}; }, NoLocalSearch{},
            {.colonies = 2, .first = r, .local = 1}, exchange,
            [&](const IslandReport& report) {
              observe(report);
              if (r == 1 && report.run.iteration == 3) throw std::runtime_error("observer failed");
            });
      });
  EXPECT_EQ(end.threw, (std::vector<int>{1, 1}));
  EXPECT_EQ(end.last_iteration, (std::vector<std::uint64_t>{3, 3}));
}

TEST(Islands, StopsWhenAnyColonyReachesTheTarget) {
  const EuclideanTsp problem = circle(12, 6);
  Parameters p = mmas_parameters(3);
  p.ants = 12;
  const double optimum = around(problem).cost;
  const IslandResult result = solve_islands(
      problem, p, Termination{.max_iterations = 500, .target_cost = optimum},
      [] { return SerialBackend{}; }, NoLocalSearch{}, {.colonies = 3, .exchange_every = 1000});
  EXPECT_EQ(result.run.reason, StopReason::target);
  EXPECT_EQ(result.run.best.cost, optimum);
  EXPECT_LT(result.run.iterations, 500U);
  EXPECT_EQ(result.run.best_iteration, result.run.iterations);
}

TEST(Islands, AStopRequestEndsTheRunAfterTheCurrentIteration) {
  const EuclideanTsp problem(20, 6, 31);
  std::stop_source source;
  source.request_stop();
  const IslandResult result = solve_islands(
      problem, mmas_parameters(1), Termination{.max_iterations = 50, .stop = source.get_token()},
      [] { return SerialBackend{}; }, NoLocalSearch{}, {.colonies = 2});
  EXPECT_EQ(result.run.reason, StopReason::interrupted);
  EXPECT_EQ(result.run.iterations, 1U);
  EXPECT_EQ(result.run.best.cost, problem.cost(result.run.best.path));
}

TEST(Islands, RejectsNonsense) {
  const EuclideanTsp problem(20, 6, 37);
  const auto run = [&](IslandSettings s) {
    return solve_islands(
        problem, mmas_parameters(1), Termination{.max_iterations = 5},
        [] { return SerialBackend{}; }, NoLocalSearch{}, s);
  };
  EXPECT_THROW(run({.colonies = 0}), std::invalid_argument);
  EXPECT_THROW(run({.colonies = 2, .exchange_every = 0}), std::invalid_argument);
  EXPECT_THROW(run({.colonies = 2, .first = 2}), std::invalid_argument);
  EXPECT_THROW(run({.colonies = 2, .first = 1, .local = 2}), std::invalid_argument);
}

}  // namespace
}  // namespace antslam::aco
