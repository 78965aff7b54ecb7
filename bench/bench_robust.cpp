// Choosing loop closures (docs/robust-closures.md): the pairwise consistency of every pair of
// closures and the ants' maximum clique on manhattan3500 with 0 and 1000 random false closures
// (2099 and 3099 closures: 2.2 and 4.8 million pairs), on 1 and 2 threads.
#include <benchmark/benchmark.h>

#include <cstdint>

#include "antslam/clique/aco_search.hpp"
#include "antslam/clique/graph.hpp"
#include "antslam/slamgraph/chain.hpp"
#include "antslam/slamgraph/consistency.hpp"
#include "antslam/slamgraph/g2o.hpp"
#include "antslam/slamgraph/outliers.hpp"

namespace {

using namespace antslam;

struct Spoiled {
  slam::PoseGraph graph;
  slam::ChainSplit split;
};

Spoiled manhattan(std::int64_t outliers) {
  const slam::PoseGraph g = slam::read_g2o_file(ANTSLAM_DATA_DIR "/posegraphs/manhattan3500.g2o");
  Spoiled s{slam::add_outliers(g, {.count = static_cast<std::size_t>(outliers)}).graph, {}};
  s.split = slam::split_chain(s.graph, "manhattan3500");
  return s;
}

/// 0 and 1000 false closures, 1 and 2 threads, wall-clock milliseconds.
void outliers_and_threads(benchmark::internal::Benchmark* b) {
  for (const std::int64_t outliers : {0, 1000})
    for (const std::int64_t threads : {1, 2}) b->Args({outliers, threads});
  b->Unit(benchmark::kMillisecond)->UseRealTime();
}

void BM_PairwiseConsistency(benchmark::State& state) {
  const Spoiled s = manhattan(state.range(0));
  const slam::ConsistencySettings settings{.threads = static_cast<std::size_t>(state.range(1))};
  std::size_t pairs = 0;
  for (auto _ : state) {
    const slam::ConsistencyGraph g = slam::pairwise_consistency(s.graph, s.split, settings);
    pairs = g.closures * (g.closures - 1) / 2;
    benchmark::DoNotOptimize(g.pairs.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pairs));
}
BENCHMARK(BM_PairwiseConsistency)->Apply(outliers_and_threads);

// 20 iterations of MAX-MIN ants with (1,2)-swaps on the consistency graph.
void BM_AntClique(benchmark::State& state) {
  const Spoiled s = manhattan(state.range(0));
  const slam::ConsistencyGraph c = slam::pairwise_consistency(s.graph, s.split, {.threads = 2});
  const clique::Graph g(c.closures, c.pairs);
  clique::AcoSearchSettings settings;
  settings.termination = {.max_iterations = 20};
  settings.threads = static_cast<std::size_t>(state.range(1));
  for (auto _ : state) {
    const clique::AcoSearchResult r = clique::maximum_clique_aco(g, settings);
    benchmark::DoNotOptimize(r.clique.weight);
  }
}
BENCHMARK(BM_AntClique)->Apply(outliers_and_threads);

}  // namespace

BENCHMARK_MAIN();
