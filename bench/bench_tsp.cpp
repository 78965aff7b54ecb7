// TSP throughput: tours constructed per second against instance size and thread count, and
// the cost of one local search from an ant's tour. Instances: the bundled TSPLIB files and a
// seeded 20,000-city random instance.
//
//   build/bench/bench_tsp --benchmark_filter=Construct
//   build/bench/bench_tsp --benchmark_filter=ConstructFallback
//   build/bench/bench_tsp --benchmark_filter=LocalSearch   (array and two-level tours)

#include <benchmark/benchmark.h>

#include <limits>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "antslam/aco/backend_omp.hpp"
#include "antslam/aco/permutation_family.hpp"
#include "antslam/aco/rules.hpp"
#include "antslam/aco/update_mmas.hpp"
#include "antslam/tsp/generator.hpp"
#include "antslam/tsp/local_search.hpp"
#include "antslam/tsp/problem.hpp"
#include "antslam/tsp/tsplib.hpp"

namespace {

using namespace antslam;

const std::vector<std::string> kInstances = {"kroA100", "pr1002", "pr2392", "E20000"};

/// Instances are loaded once per process.
const tsp::TspProblem& problem(std::size_t index) {
  static std::map<std::size_t, std::unique_ptr<tsp::TspProblem>> cache;
  auto& slot = cache[index];
  if (!slot) {
    const std::string& name = kInstances.at(index);
    tsp::Instance instance =
        name == "E20000"
            ? tsp::random_uniform_instance(20000, 1)
            : tsp::read_instance(std::string(ANTSLAM_DATA_DIR) + "/tsplib/" + name + ".tsp");
    slot = std::make_unique<tsp::TspProblem>(std::move(instance));
  }
  return *slot;
}

/// MMAS trails as at the start of a run (tau_max everywhere).
aco::PermutationFamily<tsp::TspProblem> fresh_family(const tsp::TspProblem& p, std::size_t ants) {
  aco::PermutationFamily<tsp::TspProblem> family(p, 1.0, 2.0);
  family.reserve_ants(ants);
  aco::MaxMinUpdate update;
  update.initialize(family.trail(), family.init_context(ants, false));
  family.prepare(aco::RandomProportional{});
  return family;
}

/// Arguments: instance index, threads. One benchmark iteration builds 25 tours.
void BM_Construct(benchmark::State& state) {
  const tsp::TspProblem& p = problem(static_cast<std::size_t>(state.range(0)));
  constexpr std::size_t kAnts = 25;
  auto family = fresh_family(p, kAnts);
  aco::OmpBackend backend(static_cast<std::size_t>(state.range(1)));
  std::vector<std::vector<std::uint32_t>> tours(kAnts);
  std::uint64_t round = 0;
  for (auto _ : state) {
    ++round;
    backend.for_each(kAnts, [&](std::size_t a) {
      aco::Rng rng = aco::ant_stream(1, round, a);
      family.construct(a, tours[a], rng, aco::RandomProportional{});
    });
    benchmark::DoNotOptimize(tours.front().data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kAnts));
  state.SetLabel(kInstances[static_cast<std::size_t>(state.range(0))] + " tours");
}
BENCHMARK(BM_Construct)
    ->ArgsProduct({{0, 1, 2, 3}, {1, 2}})
    ->ArgNames({"instance", "threads"})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

/// TspProblem without its nearest-unvisited search: the engine falls back to its O(n) scan.
struct ScanFallback {
  const tsp::TspProblem* p;
  std::size_t size() const { return p->size(); }
  double distance(std::uint32_t i, std::uint32_t j) const { return p->distance(i, j); }
  std::span<const std::uint32_t> candidates(std::uint32_t i) const { return p->candidates(i); }
  double cost(std::span<const std::uint32_t> t) const { return p->cost(t); }
};

/// The construction fallback with the grid search and with the engine's scan, serial.
/// Arguments: instance index, 1 = grid search, 0 = scan.
void BM_ConstructFallback(benchmark::State& state) {
  const tsp::TspProblem& p = problem(static_cast<std::size_t>(state.range(0)));
  const ScanFallback scan{&p};
  const auto run = [&](auto& family) {
    family.reserve_ants(1);
    aco::MaxMinUpdate update;
    update.initialize(family.trail(), family.init_context(1, false));
    family.prepare(aco::RandomProportional{});
    std::vector<std::uint32_t> tour;
    std::uint64_t round = 0;
    for (auto _ : state) {
      aco::Rng rng = aco::ant_stream(1, ++round, 0);
      family.construct(0, tour, rng, aco::RandomProportional{});
      benchmark::DoNotOptimize(tour.data());
    }
  };
  if (state.range(1) == 1) {
    aco::PermutationFamily<tsp::TspProblem> family(p, 1.0, 2.0);
    run(family);
  } else {
    aco::PermutationFamily<ScanFallback> family(scan, 1.0, 2.0);
    run(family);
  }
  state.SetItemsProcessed(state.iterations());
  state.SetLabel(kInstances[static_cast<std::size_t>(state.range(0))] +
                 (state.range(1) == 1 ? " grid search" : " scan"));
}
BENCHMARK(BM_ConstructFallback)
    ->ArgsProduct({{1, 2, 3}, {1, 0}})
    ->ArgNames({"instance", "grid"})
    ->Unit(benchmark::kMillisecond);

/// Arguments: instance index, local search kind, tour (0: array, 1: two-level). One benchmark
/// iteration improves one freshly constructed ant tour (construction excluded from the timing).
void BM_LocalSearch(benchmark::State& state) {
  const tsp::TspProblem& p = problem(static_cast<std::size_t>(state.range(0)));
  const auto kind = static_cast<tsp::LocalSearchKind>(state.range(1));
  auto family = fresh_family(p, 1);
  const bool two_level = state.range(2) != 0;
  const tsp::TourLocalSearch ls(
      {.kind = kind, .two_level_from = two_level ? 0 : std::numeric_limits<std::size_t>::max()});
  auto workspace = ls.make_workspace(p);
  std::vector<std::uint32_t> tour;
  std::uint64_t round = 0, moves = 0;
  double gain = 0.0;
  for (auto _ : state) {
    state.PauseTiming();
    aco::Rng rng = aco::ant_stream(2, ++round, 0);
    family.construct(0, tour, rng, aco::RandomProportional{});
    const double before = p.cost(tour);
    state.ResumeTiming();
    ls.improve(p, tour, workspace, rng, {});
    state.PauseTiming();
    moves += workspace.stats.moves;
    gain += 1.0 - p.cost(tour) / before;
    state.ResumeTiming();
  }
  state.counters["moves"] = static_cast<double>(moves) / static_cast<double>(state.iterations());
  state.counters["gain_%"] = 100.0 * gain / static_cast<double>(state.iterations());
  state.SetLabel(kInstances[static_cast<std::size_t>(state.range(0))] + " " +
                 std::string(tsp::to_string(kind)) + (two_level ? " two-level" : " array"));
}
BENCHMARK(BM_LocalSearch)
    ->ArgsProduct({{1, 2, 3}, {1, 2, 3}, {0, 1}})
    ->ArgNames({"instance", "kind", "two_level"})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
