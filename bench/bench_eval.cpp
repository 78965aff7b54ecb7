// Cost of trajectory evaluation: association (greedy nearest stamps, O((n + m) log m)) over
// trajectory size and tolerance, and the whole `antslam eval` computation on the shipped Intel
// reference with its relations.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <random>

#include "antslam/eval/association.hpp"
#include "antslam/eval/evaluation.hpp"
#include "antslam/eval/relations.hpp"

namespace {

using namespace antslam;

/// n poses at 10 Hz with +-5 ms of seeded jitter on the stamps.
slam::Trajectory jittered(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.005, 0.005);
  slam::Trajectory t(n);
  for (std::size_t i = 0; i < n; ++i)
    t[i] = {0.1 * static_cast<double>(i) + jitter(rng), slam::Pose2{static_cast<double>(i), 0, 0}};
  return t;
}

/// Args: poses, tolerance in ms (20 ms: about one candidate per pose; 1000 ms: about 20).
void BM_Associate(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const double max_dt = static_cast<double>(state.range(1)) / 1000.0;
  const slam::Trajectory estimate = jittered(n, 1), reference = jittered(n, 2);
  for (auto _ : state) benchmark::DoNotOptimize(eval::associate(estimate, reference, max_dt));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_Associate)
    ->ArgsProduct({{1000, 10000, 100000}, {20, 1000}})
    ->Unit(benchmark::kMicrosecond);

void BM_EvaluateIntel(benchmark::State& state) {
  const std::filesystem::path laser = std::filesystem::path(ANTSLAM_DATA_DIR) / "laser";
  const slam::Trajectory reference = slam::read_tum_file(laser / "intel-subset.ref.tum");
  const auto relations = eval::read_relations_file(laser / "intel.relations");
  for (auto _ : state)
    benchmark::DoNotOptimize(eval::evaluate(reference, reference, {}, relations));
}
BENCHMARK(BM_EvaluateIntel)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
