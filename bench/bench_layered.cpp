// Throughput of the engine on the synthetic layered problem, serial.
#include <benchmark/benchmark.h>

#include "antslam/aco/synthetic_layered.hpp"
#include "antslam/aco/variants.hpp"

namespace {

using namespace antslam::aco;

void BM_HybridLayered(benchmark::State& state) {
  const SyntheticLayeredProblem problem(static_cast<std::size_t>(state.range(0)), 20, 1);
  Parameters p;
  p.variant = Variant::hybrid;
  for (auto _ : state) {
    const RunResult r = solve(problem, p, {.max_iterations = 3000}, SerialBackend{});
    benchmark::DoNotOptimize(r.best.cost);
  }
  state.SetItemsProcessed(state.iterations() * 3000 * 20);
}
BENCHMARK(BM_HybridLayered)->Arg(8)->Arg(14)->Arg(23)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
