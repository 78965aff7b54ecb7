#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

#include "antslam/eval/association.hpp"
#include "trajectories.hpp"

namespace antslam::eval {
namespace {

using testing::make_trajectory;
using Match = std::pair<std::size_t, std::size_t>;  // (estimate index, reference index)

std::vector<Match> matches(const std::vector<PosePair>& pairs) {
  std::vector<Match> m;
  for (const PosePair& p : pairs) m.emplace_back(p.estimate_index, p.reference_index);
  return m;
}

slam::Trajectory stamps_only(const std::vector<double>& stamps) {
  slam::Trajectory t;
  for (double s : stamps) t.push_back({s, slam::Pose2{s, 0.0, 0.0}});
  return t;
}

/// The definition, by brute force: all pairs within max_dt sorted by (|dt|, i, j), taken
/// greedily while both poses are free.
std::vector<Match> brute_force(const slam::Trajectory& est, const slam::Trajectory& ref,
                               double max_dt) {
  std::vector<std::tuple<double, std::size_t, std::size_t>> all;
  for (std::size_t i = 0; i < est.size(); ++i)
    for (std::size_t j = 0; j < ref.size(); ++j) {
      const double dt = std::abs(ref[j].stamp - est[i].stamp);
      if (dt <= max_dt) all.emplace_back(dt, i, j);
    }
  std::sort(all.begin(), all.end());
  std::vector<bool> est_used(est.size()), ref_used(ref.size());
  std::vector<Match> m;
  for (const auto& [dt, i, j] : all) {
    if (est_used[i] || ref_used[j]) continue;
    est_used[i] = ref_used[j] = true;
    m.emplace_back(i, j);
  }
  std::sort(m.begin(), m.end(), [](const Match& a, const Match& b) { return a.second < b.second; });
  return m;
}

TEST(Associate, ToleranceAndMissingStamps) {
  const auto est = stamps_only({0.0, 1.0, 2.0, 3.005, 4.5});
  const auto ref = stamps_only({0.01, 1.03, 2.0, 3.0, 4.0});
  const auto pairs = associate(est, ref, 0.02);
  // 1.0 is 0.03 from 1.03 and 4.5 is 0.5 from 4.0: both left out.
  EXPECT_EQ(matches(pairs), (std::vector<Match>{{0, 0}, {2, 2}, {3, 3}}));
  EXPECT_DOUBLE_EQ(pairs[2].stamp, 3.0);
  EXPECT_DOUBLE_EQ(pairs[2].estimate.x, 3.005);
  EXPECT_DOUBLE_EQ(pairs[2].reference.x, 3.0);
  EXPECT_EQ(matches(associate(est, ref, 0.0)), (std::vector<Match>{{2, 2}}));
  EXPECT_EQ(associate(est, ref, 0.031).size(), 4U);
}

TEST(Associate, IsOneToOneAndTakesTheNearestFirst) {
  // Both estimates are within tolerance of the single reference pose; the nearer one wins.
  EXPECT_EQ(matches(associate(stamps_only({1.0, 1.01}), stamps_only({1.008}), 0.02)),
            (std::vector<Match>{{1, 0}}));
  // The estimate takes the nearer of two reference poses.
  EXPECT_EQ(matches(associate(stamps_only({1.01}), stamps_only({1.004, 1.012}), 0.02)),
            (std::vector<Match>{{0, 1}}));
  // Global nearest first: estimate 1 takes reference 0 (dt 0.001), so estimate 0 falls back to
  // reference 1 (dt 0.02) if the tolerance allows it, and stays unmatched otherwise.
  const auto est = stamps_only({0.0, 0.01}), ref = stamps_only({0.009, 0.02});
  EXPECT_EQ(matches(associate(est, ref, 0.02)), (std::vector<Match>{{1, 0}, {0, 1}}));
  EXPECT_EQ(matches(associate(est, ref, 0.015)), (std::vector<Match>{{1, 0}}));
}

TEST(Associate, MatchesBruteForceOnRandomStamps) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> stamp(0.0, 2.0);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<double> a(rng() % 25), b(rng() % 25);
    // Stamps on a 5 ms grid, so that equal stamps and tied distances occur.
    for (double& s : a) s = std::round(stamp(rng) * 200.0) / 200.0;
    for (double& s : b) s = std::round(stamp(rng) * 200.0) / 200.0;
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    const auto est = stamps_only(a), ref = stamps_only(b);
    for (double max_dt : {0.0, 0.004, 0.02, 0.3, 10.0})
      ASSERT_EQ(matches(associate(est, ref, max_dt)), brute_force(est, ref, max_dt))
          << "trial " << trial << " max_dt " << max_dt;
  }
}

TEST(Associate, EmptyTrajectoriesGiveNoPairs) {
  EXPECT_TRUE(associate({}, stamps_only({1.0}), 0.02).empty());
  EXPECT_TRUE(associate(stamps_only({1.0}), {}, 0.02).empty());
}

TEST(Associate, RejectsBadToleranceAndUnsortedStamps) {
  const auto t = stamps_only({1.0, 2.0});
  EXPECT_THROW(associate(t, t, -0.1), std::invalid_argument);
  EXPECT_THROW(associate(t, t, std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
  EXPECT_THROW(associate(t, t, std::numeric_limits<double>::infinity()), std::invalid_argument);
  const auto unsorted = stamps_only({2.0, 1.0});
  try {
    associate(t, unsorted, 0.02);
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "reference timestamps decrease after stamp 2 s");
  }
}

TEST(FindStamp, NearestWithinToleranceEarlierOnTie) {
  const auto t = stamps_only({1.0, 2.0, 2.0, 3.0});
  EXPECT_EQ(find_stamp(t, 1.01, 0.02), 0U);
  EXPECT_EQ(find_stamp(t, 0.99, 0.02), 0U);
  EXPECT_EQ(find_stamp(t, 2.0, 0.0), 1U);  // equal stamps: the first
  EXPECT_EQ(find_stamp(t, 2.5, 0.5), 1U);  // tie between 2.0 and 3.0: the first 2.0
  EXPECT_EQ(find_stamp(t, 3.004, 0.005), 3U);
  EXPECT_FALSE(find_stamp(t, 1.5, 0.02));
  EXPECT_FALSE(find_stamp(t, 0.5, 0.02));
  EXPECT_FALSE(find_stamp(t, 3.5, 0.02));
  EXPECT_FALSE(find_stamp({}, 1.0, 1.0));
}

}  // namespace
}  // namespace antslam::eval
