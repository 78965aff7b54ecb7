#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

#include "antslam/aco/random.hpp"
#include "antslam/aco/rules.hpp"

namespace antslam::aco {
namespace {

const std::vector<double> kWeights{1.0, 0.0, 3.0, 4.0, 2.0};

template <class Rule>
std::vector<double> distribution_of(const Rule& rule) {
  std::vector<double> p(kWeights.size());
  rule.distribution(kWeights, p);
  return p;
}

/// choose() must draw from exactly the probabilities distribution() states.
template <class Rule>
void expect_choose_matches_distribution(const Rule& rule) {
  const auto p = distribution_of(rule);
  double total = 0.0;
  for (double x : p) total += x;
  EXPECT_NEAR(total, 1.0, 1e-12);
  Rng rng(3);
  std::vector<double> count(kWeights.size(), 0.0);
  const int n = 200000;
  for (int i = 0; i < n; ++i) count[rule.choose(std::span<const double>(kWeights), rng)] += 1.0;
  for (std::size_t j = 0; j < p.size(); ++j)
    EXPECT_NEAR(count[j] / n, p[j], 0.005) << "option " << j;
  // Given the sum of the weights, choose() draws the same options from the same random numbers.
  Rng plain(5), given(5);
  const double sum = detail::sum(kWeights);
  for (int i = 0; i < 10000; ++i)
    ASSERT_EQ(rule.choose(std::span<const double>(kWeights), plain),
              rule.choose(std::span<const double>(kWeights), sum, given))
        << "draw " << i;
}

TEST(Rules, RandomProportionalIsEq1) {
  const auto p = distribution_of(RandomProportional{});
  EXPECT_DOUBLE_EQ(p[0], 0.1);
  EXPECT_DOUBLE_EQ(p[1], 0.0);
  EXPECT_DOUBLE_EQ(p[3], 0.4);
  expect_choose_matches_distribution(RandomProportional{});
}

TEST(Rules, PseudoRandomProportionalAddsQ0ToTheBest) {
  const auto p = distribution_of(PseudoRandomProportional{0.9});
  EXPECT_NEAR(p[3], 0.9 + 0.1 * 0.4, 1e-15);
  EXPECT_NEAR(p[0], 0.1 * 0.1, 1e-15);
  expect_choose_matches_distribution(PseudoRandomProportional{0.9});
}

TEST(Rules, UniformExplorationMixesP0Uniform) {
  const auto p = distribution_of(UniformExploration{0.3});
  EXPECT_NEAR(p[1], 0.3 / 5, 1e-15);  // zero weight, reachable only by exploration
  EXPECT_NEAR(p[2], 0.3 / 5 + 0.7 * 0.3, 1e-15);
  expect_choose_matches_distribution(UniformExploration{0.3});
}

TEST(Rules, AllZeroWeightsFallBackToUniform) {
  const std::vector<double> zero(4, 0.0);
  std::vector<double> p(4);
  RandomProportional{}.distribution(zero, p);
  for (double x : p) EXPECT_DOUBLE_EQ(x, 0.25);
  Rng rng(1);
  for (int i = 0; i < 100; ++i)
    EXPECT_LT(RandomProportional{}.choose(std::span<const double>(zero), rng), 4U);
}

}  // namespace
}  // namespace antslam::aco
