// Iterations per second of the TSP's default colony (MAX-MIN + 3-opt with focused construction,
// tsp::SolverSettings{}) on a seeded random uniform instance, against the thread count. The
// colony first runs 20 iterations untimed (the first builds every tour from nothing and searches
// it from every city; focused construction starts with the second), then each benchmark
// iteration is one colony iteration. Results are bit-identical for every thread count (tested
// in tests/tsp and tests/contract), so the ratio of the rates is the speed-up.
//
//   build/bench/bench_tsp_colony --benchmark_filter=ColonyStep
//
// BM_MaxMinTrailUpdate times the serial-or-chunked part alone: the trail update of one iteration.

#include <benchmark/benchmark.h>

#include <map>
#include <memory>

#include "antslam/aco/backend_factory.hpp"
#include "antslam/aco/variants.hpp"
#include "antslam/tsp/generator.hpp"
#include "antslam/tsp/local_search.hpp"
#include "antslam/tsp/problem.hpp"
#include "antslam/tsp/solver.hpp"

namespace {

using namespace antslam;

const tsp::TspProblem& uniform_problem(std::size_t n) {
  static std::map<std::size_t, std::unique_ptr<tsp::TspProblem>> cache;
  auto& slot = cache[n];
  if (!slot) slot = std::make_unique<tsp::TspProblem>(tsp::random_uniform_instance(n, 1));
  return *slot;
}

/// The default colony on state's instance (range 0: cities) and backend (range 1: threads),
/// after 20 untimed iterations; then body(colony, backend).
template <class Body>
void with_warm_colony(benchmark::State& state, Body&& body) {
  const tsp::TspProblem& p = uniform_problem(static_cast<std::size_t>(state.range(0)));
  const auto threads = static_cast<std::size_t>(state.range(1));
  const tsp::SolverSettings settings;
  const aco::Parameters parameters = tsp::resolved_parameters(p, settings);
  aco::AnyBackend backend = aco::make_backend(aco::BackendKind::automatic, threads);
  aco::with_colony(p, parameters, backend, tsp::TourLocalSearch(settings.local_search),
                   [&](auto& colony) {
                     for (int warm = 0; warm < 20; ++warm) colony.step();
                     body(colony, backend);
                     return 0;
                   });
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

/// Arguments: cities, threads.
void BM_ColonyStep(benchmark::State& state) {
  with_warm_colony(state, [&](auto& colony, aco::AnyBackend&) {
    for (auto _ : state) colony.step();
    state.counters["best"] = colony.best().cost;
  });
}
BENCHMARK(BM_ColonyStep)
    ->ArgsProduct({{15000}, {1, 2}})
    ->ArgNames({"cities", "threads"})
    ->MinTime(5.0)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

/// MAX-MIN's end-of-iteration trail update (evaporation, the best tour's deposit, the trail
/// limits) on the colony's trail after 20 iterations, its entries split over the backend's
/// threads (aco/chunked_for.hpp). Arguments: cities, threads.
void BM_MaxMinTrailUpdate(benchmark::State& state) {
  with_warm_colony(state, [&](auto& colony, aco::AnyBackend& backend) {
    const aco::ChunkedFor parallel(backend);
    auto trail = colony.trail();
    const aco::Solution& best = colony.best();
    const double tau_max = trail.max_value();
    for (auto _ : state) {
      trail.evaporate(0.2, parallel);
      trail.deposit(best.path, 1.0 / best.cost, parallel);
      trail.clamp(tau_max / 1000.0, tau_max, parallel);
    }
    benchmark::DoNotOptimize(trail.values().data());
  });
}
BENCHMARK(BM_MaxMinTrailUpdate)
    ->ArgsProduct({{15000}, {1, 2}})
    ->ArgNames({"cities", "threads"})
    ->MinTime(2.0)
    ->UseRealTime()
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
