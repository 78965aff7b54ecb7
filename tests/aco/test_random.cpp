#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "antslam/aco/random.hpp"

namespace antslam::aco {
namespace {

TEST(Random, SameSeedSameStream) {
  Rng a(7), b(7), c(8);
  bool differs = false;
  for (int i = 0; i < 100; ++i) {
    const auto x = a();
    EXPECT_EQ(x, b());
    differs |= x != c();
  }
  EXPECT_TRUE(differs);
}

TEST(Random, AntStreamsAreDistinctPerIterationAndAnt) {
  EXPECT_NE(ant_stream(1, 1, 0)(), ant_stream(1, 1, 1)());
  EXPECT_NE(ant_stream(1, 1, 0)(), ant_stream(1, 2, 0)());
  EXPECT_NE(ant_stream(1, 1, 0)(), ant_stream(2, 1, 0)());
  EXPECT_EQ(ant_stream(3, 4, 5)(), ant_stream(3, 4, 5)());
}

TEST(Random, UniformInUnitIntervalWithRightMean) {
  Rng rng(11);
  double sum = 0.0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double u = rng.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
  }
  EXPECT_NEAR(sum / n, 0.5, 0.005);
}

TEST(Random, BelowIsUniformOverItsRange) {
  Rng rng(5);
  std::vector<int> count(7, 0);
  const int n = 70000;
  for (int i = 0; i < n; ++i) {
    const auto v = rng.below(7);
    ASSERT_LT(v, 7U);
    ++count[v];
  }
  double chi2 = 0.0;
  for (int c : count) chi2 += (c - 10000.0) * (c - 10000.0) / 10000.0;
  EXPECT_LT(chi2, 22.46);  // chi-square, 6 dof, p = 0.001
}

}  // namespace
}  // namespace antslam::aco
