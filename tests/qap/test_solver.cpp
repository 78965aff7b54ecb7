// The QAP on the engine: MMAS-QAP with pair-swap local search finds the brute-force optimum of
// small random instances and chr12a's optimum, every variant runs, and one seed gives the same
// run on every backend and thread count.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <span>
#include <vector>

#include "antslam/qap/qaplib.hpp"
#include "antslam/qap/solver.hpp"
#include "qap_test_support.hpp"

namespace antslam::qap {
namespace {

std::int64_t brute_force_optimum(const Instance& instance) {
  std::vector<std::uint32_t> p(instance.size());
  std::iota(p.begin(), p.end(), 0U);
  std::int64_t best = std::numeric_limits<std::int64_t>::max();
  do {
    best = std::min(best, instance.cost(p));
  } while (std::next_permutation(p.begin(), p.end()));
  return best;
}

/// Whether p is a permutation of 0..n-1.
bool is_permutation(std::span<const std::uint32_t> p) {
  std::vector<std::uint32_t> identity(p.size());
  std::iota(identity.begin(), identity.end(), 0U);
  return std::is_permutation(p.begin(), p.end(), identity.begin(), identity.end());
}

TEST(QapSolver, MmasQapDefaults) {
  const aco::Parameters p = resolved_parameters({});
  EXPECT_EQ(p.variant, aco::Variant::mmas);
  EXPECT_EQ(p.ants, 5U);
  EXPECT_DOUBLE_EQ(p.rho, 0.2);  // trail persistence 0.8
  SolverSettings without;
  without.local_search = false;
  EXPECT_EQ(resolved_parameters(without).ants, 20U);
}

TEST(QapSolver, FindsTheBruteForceOptimumOfSmallInstances) {
  for (std::size_t n = 3; n <= 7; ++n)
    for (bool symmetric : {true, false}) {
      const QapProblem problem(testing::random_instance(n, symmetric, 100 + n));
      const std::int64_t optimum = brute_force_optimum(problem.instance());
      SolverSettings s;
      s.aco.seed = n;
      const aco::RunResult r = solve(problem, s, {.max_iterations = 100});
      EXPECT_EQ(r.best.cost, static_cast<double>(optimum)) << "n = " << n;
      EXPECT_EQ(problem.instance().cost(r.best.path), optimum);
      EXPECT_TRUE(is_permutation(r.best.path));
    }
}

TEST(QapSolver, ReachesTheOptimumOfChr12a) {
  const QapProblem problem(read_qaplib(testing::data("chr12a.dat")));
  SolverSettings s;
  s.aco.seed = 1;
  const aco::RunResult r = solve(problem, s, {.max_iterations = 500, .target_cost = 9552.0});
  EXPECT_EQ(r.best.cost, 9552.0);
  EXPECT_EQ(r.reason, aco::StopReason::target);
  EXPECT_EQ(problem.instance().cost(r.best.path), 9552);
}

TEST(QapSolver, EveryVariantWithAndWithoutLocalSearch) {
  const QapProblem problem(read_qaplib(testing::data("nug12.dat")));
  for (aco::Variant v : aco::all_variants())
    for (bool local_search : {true, false}) {
      SolverSettings s;
      s.aco.variant = v;
      s.local_search = local_search;
      const aco::RunResult r = solve(problem, s, {.max_iterations = 20});
      EXPECT_TRUE(is_permutation(r.best.path)) << aco::to_string(v);
      EXPECT_EQ(r.best.cost, static_cast<double>(problem.instance().cost(r.best.path)));
      EXPECT_GE(r.best.cost, 578.0);  // nug12's optimum
    }
}

/// Every iteration's best cost and the final best assignment of a run.
struct Trace {
  std::vector<double> iteration_best;
  std::vector<std::uint32_t> best;
  bool operator==(const Trace&) const = default;
};

Trace run(const QapProblem& problem, aco::Variant variant, bool local_search,
          aco::BackendKind backend, std::size_t threads) {
  SolverSettings s;
  s.aco.variant = variant;
  s.aco.seed = 11;
  s.local_search = local_search;
  s.backend = backend;
  s.threads = threads;
  Trace trace;
  const aco::RunResult r = solve(problem, s, {.max_iterations = 25}, [&](const auto& report) {
    trace.iteration_best.push_back(report.iteration_best);
  });
  trace.best = r.best.path;
  return trace;
}

TEST(QapSolver, SameRunOnEveryBackendAndThreadCount) {
  const QapProblem problem(read_qaplib(testing::data("tai12a.dat")));
  for (aco::Variant v : {aco::Variant::mmas, aco::Variant::acs, aco::Variant::ant_system})
    for (bool local_search : {true, false}) {
      const Trace serial = run(problem, v, local_search, aco::BackendKind::serial, 1);
      ASSERT_EQ(serial.iteration_best.size(), 25U);
      for (aco::BackendKind backend : {aco::BackendKind::omp, aco::BackendKind::tbb})
        for (std::size_t threads : {std::size_t{1}, std::size_t{2}})
          EXPECT_EQ(run(problem, v, local_search, backend, threads), serial)
              << aco::to_string(v) << " on " << threads << " thread(s)";
    }
}

}  // namespace
}  // namespace antslam::qap
