// Trail updates in chunks on a backend's threads: the chunks cover every entry exactly once, and
// evaporation, deposits and bounds give the serial pass's values bit for bit, on every trail and
// through the pheromone-update policies. Under ThreadSanitizer these tests also show that the
// chunks of one deposit touch disjoint entries.

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <numeric>
#include <random>
#include <span>
#include <vector>

#include "antslam/aco/backend_factory.hpp"
#include "antslam/aco/chunked_for.hpp"
#include "antslam/aco/edge_trail.hpp"
#include "antslam/aco/layered_trail.hpp"
#include "antslam/aco/subset_trail.hpp"
#include "antslam/aco/update_acs.hpp"
#include "antslam/aco/update_ant_system.hpp"
#include "antslam/aco/update_hybrid.hpp"
#include "antslam/aco/update_mmas.hpp"

namespace antslam::aco {
namespace {

constexpr std::size_t kLarge = 5 * ChunkedFor::kMinChunk + 7;  // several chunks, uneven

std::vector<AnyBackend> two_thread_backends() {
  return {make_backend(BackendKind::omp, 2), make_backend(BackendKind::tbb, 2)};
}

/// How many times body saw each index, and how many calls it took.
struct Coverage {
  std::vector<std::atomic<int>> seen;
  std::atomic<int> calls{0};
  explicit Coverage(std::size_t count) : seen(count) {}
  void run(const ChunkedFor& parallel, std::size_t min_chunk = ChunkedFor::kMinChunk) {
    const auto body = [&](std::size_t begin, std::size_t end) {
      ++calls;
      for (std::size_t i = begin; i < end; ++i) ++seen[i];
    };
    parallel(seen.size(), body, min_chunk);
  }
  bool every_index_once() const {
    return std::all_of(seen.begin(), seen.end(), [](const std::atomic<int>& s) { return s == 1; });
  }
};

TEST(ChunkedFor, CoversEveryIndexOnceAndSplitsOnlyLargeRanges) {
  for (AnyBackend backend : two_thread_backends()) {
    const ChunkedFor parallel(backend);
    for (const std::size_t count :
         {std::size_t{0}, std::size_t{1}, 2 * ChunkedFor::kMinChunk - 1, kLarge}) {
      Coverage coverage(count);
      coverage.run(parallel);
      EXPECT_TRUE(coverage.every_index_once()) << count;
      EXPECT_EQ(coverage.calls, count < 2 * ChunkedFor::kMinChunk ? 1 : 5) << count;
    }
    Coverage searches(3 * ChunkedFor::kMinSearchChunk + 1);  // a tour's deposit: shorter chunks
    searches.run(parallel, ChunkedFor::kMinSearchChunk);
    EXPECT_TRUE(searches.every_index_once());
    EXPECT_EQ(searches.calls, 3);
  }
}

TEST(ChunkedFor, TheDefaultAndOneThreadRunOneRange) {
  AnyBackend serial = make_backend(BackendKind::serial, 1);
  AnyBackend one_thread = make_backend(BackendKind::tbb, 1);
  for (const ChunkedFor& parallel : {ChunkedFor{}, ChunkedFor(serial), ChunkedFor(one_thread)}) {
    Coverage coverage(kLarge);
    coverage.run(parallel);
    EXPECT_TRUE(coverage.every_index_once());
    EXPECT_EQ(coverage.calls, 1);
  }
}

/// A ring of n nodes whose candidates are the 2 nearest on each side: every edge has a mirror.
EdgeTrail ring_trail(std::uint32_t n) {
  std::vector<std::uint32_t> neighbours;
  for (std::uint32_t i = 0; i < n; ++i)
    for (const std::uint32_t d : {1U, n - 1, 2U, n - 2}) neighbours.push_back((i + d) % n);
  EdgeTrail trail(n, 4, std::move(neighbours));
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.5, 2.0);
  for (std::uint32_t i = 0; i < n; ++i)  // every entry: unequal values, equal copies
    for (const std::uint32_t j : trail.neighbours(i)) {
      const double v = u(rng);
      trail.update_edge(i, j, [v](double& t) { t = v; });
    }
  return trail;
}

/// A tour mixing candidate edges (runs of consecutive nodes) and non-candidate jumps.
std::vector<std::uint32_t> mixed_tour(std::uint32_t n) {
  std::vector<std::uint32_t> tour(n);
  std::iota(tour.begin(), tour.end(), 0U);
  std::mt19937_64 rng(11);
  for (std::uint32_t b = 0; b + 64 <= n; b += 64)
    if (rng() % 2 == 0) std::shuffle(tour.begin() + b, tour.begin() + b + 64, rng);
  return tour;
}

std::vector<double> values_of(const PheromoneValues& trail) {
  return {trail.values().begin(), trail.values().end()};
}

TEST(ChunkedFor, EdgeTrailUpdatesEqualTheSerialPassBitForBit) {
  const auto n = static_cast<std::uint32_t>(kLarge);
  const std::vector<std::uint32_t> tour = mixed_tour(n);
  EdgeTrail serial = ring_trail(n);
  serial.evaporate(0.2);
  serial.deposit(tour, 0.37);
  serial.clamp(0.9, 1.5);
  for (AnyBackend backend : two_thread_backends()) {
    const ChunkedFor parallel(backend);
    EdgeTrail chunked = ring_trail(n);
    chunked.evaporate(0.2, parallel);
    chunked.deposit(tour, 0.37, parallel);
    chunked.clamp(0.9, 1.5, parallel);
    EXPECT_EQ(values_of(chunked), values_of(serial));
  }
  for (std::uint32_t e = 0; e < serial.values().size(); ++e) {  // both copies of an edge agree
    const std::uint32_t copy = serial.mirror(e);
    if (copy != EdgeTrail::kNone) {
      ASSERT_EQ(serial.entry(e), serial.entry(copy));
    }
  }
  EXPECT_GT(serial.max_value(), 1.2);  // the deposit reached the candidate edges of the tour
}

TEST(ChunkedFor, LayeredAndSubsetDepositsEqualTheSerialPass) {
  const std::vector<std::size_t> counts(kLarge, 3);
  std::vector<std::uint32_t> path(kLarge);
  for (std::size_t l = 0; l < kLarge; ++l) path[l] = static_cast<std::uint32_t>(l * 7 % 3);
  std::vector<std::uint32_t> subset;
  for (std::uint32_t e = 0; e < kLarge; e += 2) subset.push_back(e);
  LayeredTrail layered_serial(counts);
  SubsetTrail subset_serial(kLarge);
  layered_serial.fill(1.0);
  subset_serial.fill(1.0);
  layered_serial.deposit(path, 0.25);
  subset_serial.deposit(subset, 0.25);
  for (AnyBackend backend : two_thread_backends()) {
    const ChunkedFor parallel(backend);
    LayeredTrail layered(counts);
    SubsetTrail chunked_subset(kLarge);
    layered.fill(1.0);
    chunked_subset.fill(1.0);
    layered.deposit(path, 0.25, parallel);
    chunked_subset.deposit(subset, 0.25, parallel);
    EXPECT_EQ(values_of(layered), values_of(layered_serial));
    EXPECT_EQ(values_of(chunked_subset), values_of(subset_serial));
  }
  EXPECT_DOUBLE_EQ(layered_serial.at(kLarge - 1, path.back()), 1.25);
  EXPECT_DOUBLE_EQ(subset_serial.values()[2], 1.25);
  EXPECT_DOUBLE_EQ(subset_serial.values()[3], 1.0);
}

/// Three iterations of a policy on the same ants, serial and chunked: the same trail bit for bit.
template <class Update>
void expect_policy_chunks_like_serial(Update update, const char* name) {
  const auto n = static_cast<std::uint32_t>(kLarge);
  std::vector<Solution> ants(3);
  for (std::size_t a = 0; a < ants.size(); ++a) {
    ants[a].path = mixed_tour(n);
    auto& path = ants[a].path;
    std::rotate(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(100 * a), path.end());
    ants[a].cost = 1000.0 + static_cast<double>(a);
  }
  const std::vector<std::uint32_t> ranking{0, 1, 2};
  InitContext context;
  context.reference_cost = 1200.0;
  context.decisions = n;
  context.local_search = true;
  const auto run = [&](Update policy, const ChunkedFor& parallel) {
    EdgeTrail trail = ring_trail(n);
    policy.initialize(trail, context);
    for (std::uint64_t it = 1; it <= 3; ++it)
      policy.apply(trail, IterationView{ants, ranking, ants[0], ants[0], it, parallel});
    return values_of(trail);
  };
  const std::vector<double> serial = run(update, {});
  for (AnyBackend backend : two_thread_backends())
    EXPECT_EQ(run(update, ChunkedFor(backend)), serial) << name;
}

TEST(ChunkedFor, EveryUpdatePolicyGivesTheSerialTrail) {
  expect_policy_chunks_like_serial(AntSystemUpdate{}, "as");
  expect_policy_chunks_like_serial(ElitistUpdate{}, "eas");
  expect_policy_chunks_like_serial(RankUpdate{}, "ras");
  expect_policy_chunks_like_serial(MaxMinUpdate{}, "mmas");
  expect_policy_chunks_like_serial(AcsUpdate{}, "acs");
  expect_policy_chunks_like_serial(HybridUpdate{}, "hybrid");
}

}  // namespace
}  // namespace antslam::aco
