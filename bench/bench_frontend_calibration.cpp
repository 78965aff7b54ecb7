// Calibration of the scan matcher's likelihood temperature (docs/frontend.md): the mean NEES of
// the Gaussian of eqs. (5)-(6) on simulated scans, for a range of temperatures, in the three
// simulated worlds. Honest is 3; the default temperature is the one that gives about 3 on
// average. Also: the time of one NEES evaluation (matching with the eqs. (5)-(6) estimate).
//
//   build/bench/bench_frontend_calibration

#include <benchmark/benchmark.h>

#include <vector>

#include "antslam/frontend/nees.hpp"
#include "antslam/frontend/simulator.hpp"

namespace {

using namespace antslam::frontend;
using V = Eigen::Vector2d;

SimulatedRun world_run(int world) {
  SimulationSettings sim;
  sim.step = 0.3;
  if (world == 0)
    return simulate_run(room_world(),
                        std::vector<V>{V(-3, -2.3), V(3.3, -2.3), V(3.3, 2.3), V(0.5, 2.3),
                                       V(0.5, -0.5), V(-3.3, -0.5)},
                        sim, 7);
  if (world == 1) return simulate_run(loop_world(), loop_waypoints(), sim, 7);
  return simulate_run(corridor_world(), std::vector<V>{V(-20, 0), V(20, 0.3)}, sim, 7);
}

/// Args: temperature in thousandths, world (0 room, 1 loop, 2 corridor).
void BM_Nees(benchmark::State& state) {
  const SimulatedRun run = world_run(static_cast<int>(state.range(1)));
  ScanMatcherSettings settings;
  settings.temperature = static_cast<double>(state.range(0)) / 1000.0;
  NeesStats stats;
  for (auto _ : state) stats = simulated_nees(run, settings);
  state.counters["temperature"] = settings.temperature;
  state.counters["nees_mean"] = stats.mean;
  state.counters["nees_median"] = stats.median;
  state.counters["scans"] = static_cast<double>(stats.count);
}

BENCHMARK(BM_Nees)
    ->ArgsProduct({{100, 150, 200, 250, 300, 500, 1000}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
