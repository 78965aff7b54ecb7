// TSPLIB distances: hand-computed values of every type, and the lengths of official optimal
// tours (or exact optima by dynamic programming) that only the official rounding reproduces.

#include <gtest/gtest.h>

#include "antslam/tsp/distance.hpp"
#include "antslam/tsp/tsplib.hpp"
#include "tsp_test_support.hpp"

namespace antslam::tsp {
namespace {

TEST(Distance, Euc2dRoundsToNearest) {
  EXPECT_EQ(distance::euc_2d({0, 0}, {3, 4}), 5.0);
  EXPECT_EQ(distance::euc_2d({0, 0}, {1, 1}), 1.0);    // 1.414
  EXPECT_EQ(distance::euc_2d({0, 0}, {2, 3}), 4.0);    // 3.606
  EXPECT_EQ(distance::euc_2d({0, 0}, {0.5, 0}), 1.0);  // nint(0.5) = 1
  EXPECT_EQ(distance::euc_2d({1, 1}, {1, 1}), 0.0);
}

TEST(Distance, Ceil2dRoundsUp) {
  EXPECT_EQ(distance::ceil_2d({0, 0}, {3, 4}), 5.0);
  EXPECT_EQ(distance::ceil_2d({0, 0}, {1, 1}), 2.0);
  EXPECT_EQ(distance::ceil_2d({0, 0}, {0.1, 0}), 1.0);
}

TEST(Distance, AttIsPseudoEuclideanRoundedUp) {
  EXPECT_EQ(distance::att({0, 0}, {10, 0}), 4.0);    // r = 3.162: nint 3 < r, so 4
  EXPECT_EQ(distance::att({0, 0}, {30, 40}), 16.0);  // r = 15.81: nint 16 >= r
  EXPECT_EQ(distance::att({0, 0}, {10, 30}), 10.0);  // r = 10 exactly
}

TEST(Distance, GeoUsesDegreesAndMinutes) {
  // 16.47 is 16 degrees 47 minutes; TSPLIB's PI = 3.141592.
  EXPECT_DOUBLE_EQ(distance::geo_radians(16.47), 3.141592 * (16.0 + 5.0 * 0.47 / 3.0) / 180.0);
  // Negative coordinates truncate towards zero: -5.21 is -5 degrees 21 minutes.
  EXPECT_DOUBLE_EQ(distance::geo_radians(-5.21), 3.141592 * (-5.0 - 5.0 * 0.21 / 3.0) / 180.0);
  // One degree of latitude on TSPLIB's sphere: 6378.388 * pi / 180 = 111.3 km, + 1, truncated.
  EXPECT_EQ(distance::geo({0.0, 0.0}, {3.141592 / 180.0, 0.0}), 112.0);
}

struct OptimalTour {
  std::string instance;
  std::string tour;
  double length;
};

class OfficialOptimalTour : public ::testing::TestWithParam<OptimalTour> {};

TEST_P(OfficialOptimalTour, HasThePublishedLength) {
  const OptimalTour& c = GetParam();
  const Instance instance = read_instance(c.instance);
  const auto tour = read_tour(c.tour, instance.size());
  EXPECT_EQ(instance.tour_length(tour), c.length);
}

INSTANTIATE_TEST_SUITE_P(
    Tsplib, OfficialOptimalTour,
    ::testing::Values(
        OptimalTour{testing::data("eil51.tsp"), testing::data("eil51.opt.tour"), 426},
        OptimalTour{testing::data("berlin52.tsp"), testing::data("berlin52.opt.tour"), 7542},
        OptimalTour{testing::data("kroA100.tsp"), testing::data("kroA100.opt.tour"), 21282},
        OptimalTour{testing::data("ch130.tsp"), testing::data("ch130.opt.tour"), 6110},
        OptimalTour{testing::data("pcb442.tsp"), testing::data("pcb442.opt.tour"), 50778},
        OptimalTour{testing::data("pr1002.tsp"), testing::data("pr1002.opt.tour"), 259045},
        OptimalTour{testing::data("pr2392.tsp"), testing::data("pr2392.opt.tour"), 378032},
        OptimalTour{testing::fixture("att48.tsp"), testing::fixture("att48.opt.tour"), 10628},
        OptimalTour{testing::fixture("ulysses16.tsp"), testing::fixture("ulysses16.opt.tour"),
                    6859}),
    [](const auto& param_info) {
      const std::string& path = param_info.param.instance;
      const auto slash = path.find_last_of('/');
      return path.substr(slash + 1, path.find('.', slash) - slash - 1);
    });

TEST(ExactOptimum, Burma14GeoIs3323) {
  EXPECT_EQ(testing::held_karp(read_instance(testing::fixture("burma14.tsp"))), 3323.0);
}

TEST(ExactOptimum, Gr17ExplicitLowerDiagRowIs2085) {
  EXPECT_EQ(testing::held_karp(read_instance(testing::fixture("gr17.tsp"))), 2085.0);
}

TEST(ExactOptimum, Ulysses16GeoIs6859) {
  EXPECT_EQ(testing::held_karp(read_instance(testing::fixture("ulysses16.tsp"))), 6859.0);
}

}  // namespace
}  // namespace antslam::tsp
