#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "antslam/eval/statistics.hpp"

namespace antslam::eval {
namespace {

TEST(Summarize, HandComputedOddCount) {
  const std::vector<double> e{3.0, 1.0, 4.0, 1.0, 5.0};
  const ErrorStatistics s = summarize(e);
  EXPECT_EQ(s.count, 5U);
  EXPECT_DOUBLE_EQ(s.mean, 2.8);                    // 14 / 5
  EXPECT_DOUBLE_EQ(s.rmse, std::sqrt(52.0 / 5.0));  // (9 + 1 + 16 + 1 + 25) / 5
  EXPECT_DOUBLE_EQ(s.median, 3.0);
  EXPECT_NEAR(s.std, 1.6, 1e-12);  // sqrt((.04 + 3.24 + 1.44 + 3.24 + 4.84) / 5)
  EXPECT_DOUBLE_EQ(s.min, 1.0);
  EXPECT_DOUBLE_EQ(s.max, 5.0);
}

TEST(Summarize, MedianOfEvenCountIsMeanOfMiddleValues) {
  const std::vector<double> e{10.0, 1.0, 3.0, 2.0};
  EXPECT_DOUBLE_EQ(summarize(e).median, 2.5);
}

TEST(Summarize, RejectsEmpty) {
  EXPECT_THROW(summarize(std::vector<double>{}), std::invalid_argument);
}

TEST(MeanStd, UsesSampleStandardDeviation) {
  const std::vector<double> v{1.0, 2.0, 3.0, 4.0};
  const MeanStd s = mean_std(v);
  EXPECT_EQ(s.count, 4U);
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_NEAR(s.std, std::sqrt(5.0 / 3.0), 1e-12);  // (2.25 + .25 + .25 + 2.25) / (4 - 1)
}

TEST(MeanStd, SingleValueHasZeroSpreadAndEmptyIsRejected) {
  const std::vector<double> one{7.0};
  EXPECT_DOUBLE_EQ(mean_std(one).mean, 7.0);
  EXPECT_DOUBLE_EQ(mean_std(one).std, 0.0);
  EXPECT_THROW(mean_std(std::vector<double>{}), std::invalid_argument);
}

}  // namespace
}  // namespace antslam::eval
