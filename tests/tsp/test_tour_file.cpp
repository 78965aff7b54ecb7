// TSPLIB tour files: reading, a write/read round trip, and malformed tours.

#include <gtest/gtest.h>

#include <sstream>

#include "antslam/tsp/optima.hpp"
#include "antslam/tsp/tsplib.hpp"
#include "tsp_test_support.hpp"

namespace antslam::tsp {
namespace {

std::string error_of(const std::string& text, std::size_t n) {
  std::istringstream in(text);
  try {
    parse_tour(in, "x.tour", n);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(TourFile, ReadsManyIdsPerLineAndConvertsToZeroBased) {
  std::istringstream in("NAME: t\nTYPE: TOUR\nDIMENSION: 4\nTOUR_SECTION\n 1 3\n2 4 -1\nEOF\n");
  EXPECT_EQ(parse_tour(in, "t", 4), (std::vector<std::uint32_t>{0, 2, 1, 3}));
}

TEST(TourFile, RoundTrips) {
  const std::vector<std::uint32_t> tour = {4, 0, 3, 1, 2};
  std::ostringstream out;
  write_tour(out, "five.tour", tour, "length 12");
  EXPECT_NE(out.str().find("COMMENT : length 12\n"), std::string::npos);
  std::istringstream in(out.str());
  EXPECT_EQ(parse_tour(in, "t", 5), tour);
}

TEST(TourFile, ReportsMalformedTours) {
  const std::string head = "NAME: t\nTYPE: TOUR\nDIMENSION: 3\nTOUR_SECTION\n";
  EXPECT_EQ(error_of(head + "1\n2\n2\n-1\n", 3), "x.tour:7: node 2 appears twice");
  EXPECT_EQ(error_of(head + "1\n2\n4\n-1\n", 3), "x.tour:7: node id 4 is not in 1..3");
  EXPECT_EQ(error_of(head + "1\n2\n-1\nEOF\n", 3), "x.tour: TOUR_SECTION has 2 of 3 nodes");
  EXPECT_EQ(error_of(head + "1\nx\n", 3), "x.tour:6: unexpected 'x' in a tour file");
  EXPECT_EQ(error_of(head + "1 2 3 -1 1\n", 3), "x.tour:5: data after the tour's closing -1");
  EXPECT_EQ(error_of(head + "1 2.5 3 -1\n", 3), "x.tour:5: node id '2.5' is not an integer");
  EXPECT_EQ(error_of(head, 4), "x.tour:3: DIMENSION 3 does not match the instance's 4 nodes");
  EXPECT_EQ(error_of("NAME: t\nTYPE: TSP\n", 3), "x.tour:2: TYPE TSP: not a tour file");
  EXPECT_EQ(error_of("NAME: t\nTYPE: TOUR\n", 3), "x.tour: missing TOUR_SECTION");
}

TEST(KnownOptimum, ComesFromOptimaCsvBesideTheInstance) {
  EXPECT_EQ(known_optimum(testing::data("eil51.tsp")), 426.0);
  EXPECT_EQ(known_optimum(testing::data("pr2392.tsp")), 378032.0);
  EXPECT_FALSE(known_optimum(testing::data("nonexistent.tsp")).has_value());
  EXPECT_FALSE(known_optimum(testing::fixture("gr17.tsp")).has_value());  // no optima.csv
}

}  // namespace
}  // namespace antslam::tsp
