// The QAP cost against a hand computation, and Taillard's pair-swap delta against the full
// recomputation for every swap of random symmetric and asymmetric instances.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <utility>
#include <vector>

#include "antslam/qap/instance.hpp"
#include "antslam/qap/local_search.hpp"
#include "qap_test_support.hpp"

namespace antslam::qap {
namespace {

// A = [0 1 2; 3 0 4; 5 6 0] (flows), B = [0 7 8; 9 0 10; 11 12 0] (distances), p = (1, 2, 0):
// facility 0 at location 1, 1 at 2, 2 at 0. Nonzero terms a_ij b_p(i)p(j):
//   a01 b12 = 1 * 10 = 10    a02 b10 = 2 * 9 = 18    a10 b21 = 3 * 12 = 36
//   a12 b20 = 4 * 11 = 44    a20 b01 = 5 * 7 = 35    a21 b02 = 6 * 8 = 48     sum = 191
TEST(QapCost, ThreeByThreeByHand) {
  const Instance instance(3, {0, 1, 2, 3, 0, 4, 5, 6, 0}, {0, 7, 8, 9, 0, 10, 11, 12, 0});
  const std::vector<std::uint32_t> p{1, 2, 0};
  EXPECT_EQ(instance.cost(p), 191);
  const std::vector<std::uint32_t> identity{0, 1, 2};
  // 1*7 + 2*8 + 3*9 + 4*10 + 5*11 + 6*12 = 217
  EXPECT_EQ(instance.cost(identity), 217);
}

TEST(QapCost, DiagonalEntriesCount) {
  const Instance instance(2, {2, 0, 0, 3}, {5, 0, 0, 7});
  EXPECT_EQ(instance.cost(std::vector<std::uint32_t>{0, 1}), 2 * 5 + 3 * 7);
  EXPECT_EQ(instance.cost(std::vector<std::uint32_t>{1, 0}), 2 * 7 + 3 * 5);
}

TEST(QapInstance, RefusesNegativeEntriesAndOverflow) {
  EXPECT_THROW(Instance(2, {0, -1, 0, 0}, {0, 1, 1, 0}), std::invalid_argument);
  EXPECT_THROW(Instance(2, {0, 1, 0}, {0, 1, 1, 0}), std::invalid_argument);
  constexpr std::int64_t kBig = std::int64_t{1} << 31;
  EXPECT_THROW(Instance(2, {0, kBig, 0, 0}, {0, kBig, 0, 0}), std::invalid_argument);
  EXPECT_NO_THROW(Instance(2, {0, kBig, 0, 0}, {0, kBig / 4, 0, 0}));
}

TEST(QapInstance, CostFitsIsExactAtTheLimit) {
  constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
  EXPECT_TRUE(cost_fits(1, kMax, 1));
  EXPECT_TRUE(cost_fits(2, kMax / 4, 1));
  EXPECT_FALSE(cost_fits(2, kMax / 4 + 1, 1));
  EXPECT_TRUE(cost_fits(3, 0, kMax));
}

void expect_delta_is_recomputation(const Instance& instance, std::uint64_t seed) {
  const std::size_t n = instance.size();
  std::vector<std::uint32_t> p(n);
  std::iota(p.begin(), p.end(), 0U);
  aco::Rng rng(seed);
  std::shuffle(p.begin(), p.end(), rng);
  const std::int64_t cost = instance.cost(p);
  for (std::uint32_t r = 0; r < n; ++r)
    for (std::uint32_t s = 0; s < n; ++s) {
      if (r == s) continue;
      std::vector<std::uint32_t> swapped = p;
      std::swap(swapped[r], swapped[s]);
      ASSERT_EQ(swap_delta(instance, p, r, s), instance.cost(swapped) - cost)
          << "swap " << r << ", " << s << " of n = " << n;
    }
}

TEST(SwapDelta, EqualsRecomputationOnSymmetricInstances) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed)
    expect_delta_is_recomputation(testing::random_instance(4 + 3 * seed, true, seed), seed);
}

TEST(SwapDelta, EqualsRecomputationOnAsymmetricInstances) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed)
    expect_delta_is_recomputation(testing::random_instance(4 + 3 * seed, false, 10 + seed), seed);
}

TEST(PairSwapLocalSearch, EndsInATwoExchangeOptimumNeverWorse) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const QapProblem problem(testing::random_instance(15, seed % 2 == 0, seed));
    const Instance& instance = problem.instance();
    std::vector<std::uint32_t> p(15);
    std::iota(p.begin(), p.end(), 0U);
    aco::Rng rng(seed);
    std::shuffle(p.begin(), p.end(), rng);
    const std::int64_t before = instance.cost(p);
    PairSwapLocalSearch search;
    PairSwapLocalSearch::Workspace ws = search.make_workspace(problem);
    search.improve(problem, p, ws, rng, {});
    EXPECT_LT(instance.cost(p), before);
    std::vector<std::uint32_t> sorted = p;
    std::sort(sorted.begin(), sorted.end());
    for (std::uint32_t i = 0; i < 15; ++i) ASSERT_EQ(sorted[i], i);
    for (std::uint32_t r = 0; r < 15; ++r)
      for (std::uint32_t s = r + 1; s < 15; ++s) ASSERT_GE(swap_delta(instance, p, r, s), 0);
  }
}

}  // namespace
}  // namespace antslam::qap
