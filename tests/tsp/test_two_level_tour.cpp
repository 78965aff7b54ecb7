// The two-level tour against brute force: after every path reversal it holds the expected cycle
// (the path a..b reversed in a plain vector), in either orientation; succ, pred, between and
// the written tour agree with it; the number of segments stays bounded.

#include <gtest/gtest.h>

#include <cmath>

#include "antslam/tsp/two_level_tour.hpp"
#include "tsp_test_support.hpp"

namespace antslam::tsp {
namespace {

/// b on the path from a to c along `cycle` (forward) or against it.
bool between_in(const std::vector<std::uint32_t>& cycle, std::uint32_t a, std::uint32_t b,
                std::uint32_t c, bool forward) {
  const std::size_t n = cycle.size();
  std::vector<std::size_t> at(n);
  for (std::size_t p = 0; p < n; ++p) at[cycle[p]] = p;
  const auto steps = [&](std::uint32_t from, std::uint32_t to) {
    return forward ? (at[to] + n - at[from]) % n : (at[from] + n - at[to]) % n;
  };
  return steps(a, b) <= steps(a, c);
}

void expect_holds(const TwoLevelTour& tour, const std::vector<std::uint32_t>& expected,
                  aco::Rng& rng) {
  const auto n = static_cast<std::uint32_t>(expected.size());
  const bool same = tour.succ(expected[0]) == expected[1 % n];  // orientation against expected
  for (std::uint32_t p = 0; p < n; ++p) {
    const std::uint32_t c = expected[p], after = expected[(p + 1) % n];
    const std::uint32_t before = expected[(p + n - 1) % n];
    ASSERT_EQ(tour.succ(c), same ? after : before);
    ASSERT_EQ(tour.pred(c), same ? before : after);
  }
  for (int triple = 0; triple < 50; ++triple) {
    const std::uint32_t a = rng.below(n), b = rng.below(n), c = rng.below(n);
    for (const bool forward : {true, false})
      ASSERT_EQ(tour.between(a, b, c, forward), between_in(expected, a, b, c, forward == same));
  }
  std::vector<std::uint32_t> written;
  tour.copy_to(written);
  ASSERT_EQ(written.size(), n);
  for (std::uint32_t p = 0; p < n; ++p) ASSERT_EQ(written[(p + 1) % n], tour.succ(written[p]));
}

TEST(TwoLevelTour, ReversalsGiveTheCycleOfBruteForce) {
  for (std::size_t n : {4U, 5U, 6U, 9U, 31U, 100U, 400U}) {
    SCOPED_TRACE(n);
    const TspProblem problem(testing::random_instance(n, 7 + n, EdgeWeightType::euc_2d));
    aco::Rng rng(n);
    std::vector<std::uint32_t> expected = testing::random_tour(n, rng);
    TwoLevelTour tour;
    tour.assign(expected, problem);
    const std::size_t after_cut = tour.segment_count();
    const auto size = static_cast<std::size_t>(std::lround(std::sqrt(static_cast<double>(n))));
    EXPECT_EQ(after_cut, (n + size - 1) / size);  // segments of round(sqrt n) cities
    expect_holds(tour, expected, rng);
    for (int step = 0; step < 600; ++step) {
      // Mostly short paths (as local search makes), some of any length.
      const auto a = rng.below(static_cast<std::uint32_t>(n));
      std::uint32_t b = rng.below(static_cast<std::uint32_t>(n));
      if (step % 3 != 0) {
        b = a;
        for (std::uint32_t s = rng.below(5); s > 0; --s) b = tour.succ(b);
      }
      // The tour's forward path a..b is, against the reference's orientation, its path b..a.
      const bool same = tour.succ(expected[0]) == expected[1];
      expected =
          same ? testing::reversed_path(expected, a, b) : testing::reversed_path(expected, b, a);
      tour.reverse_path(a, b);
      ASSERT_LE(tour.segment_count(), 2 * after_cut);
      ASSERT_NO_FATAL_FAILURE(expect_holds(tour, expected, rng));
    }
  }
}

TEST(TwoLevelTour, NextLengthIsTheDistanceToTheNeighbour) {
  const TspProblem problem(testing::random_instance(50, 3, EdgeWeightType::att));
  aco::Rng rng(3);
  TwoLevelTour tour;
  tour.assign(testing::random_tour(50, rng), problem);
  tour.reverse_path(3, 17);
  for (std::uint32_t c = 0; c < 50; ++c) {
    EXPECT_EQ(tour.next_length(c, true), problem.distance(c, tour.succ(c)));
    EXPECT_EQ(tour.next_length(c, false), problem.distance(c, tour.pred(c)));
  }
}

}  // namespace
}  // namespace antslam::tsp
