// TSPLIB instance reader and writer: accepted variations, every explicit matrix layout, a
// write/read round trip, and malformed files failing with "file:line: problem".

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>

#include "antslam/tsp/generator.hpp"
#include "antslam/tsp/tsplib.hpp"
#include "tsp_test_support.hpp"

namespace antslam::tsp {
namespace {

using ::testing::HasSubstr;

Instance parse(const std::string& text) {
  std::istringstream in(text);
  return parse_instance(in, "x.tsp");
}

/// The message of the error parse() throws ("" if none).
std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

const std::string kHeader = "NAME : five\nTYPE : TSP\nDIMENSION : 5\nEDGE_WEIGHT_TYPE : EUC_2D\n";
const std::string kCoords = "NODE_COORD_SECTION\n1 0 0\n2 3 4\n3 6 8\n4 0 8\n5 6 0\n";

TEST(TsplibReader, ReadsACoordinateInstance) {
  const Instance i = parse(kHeader + "COMMENT : a test\n" + kCoords + "EOF\n");
  EXPECT_EQ(i.name(), "five");
  EXPECT_EQ(i.comment, "a test");
  EXPECT_EQ(i.size(), 5U);
  EXPECT_EQ(i.type(), EdgeWeightType::euc_2d);
  EXPECT_EQ(i.distance(0, 1), 5.0);
  EXPECT_EQ(i.distance(1, 2), 5.0);
  EXPECT_EQ(i.distance(0, 2), 10.0);
}

TEST(TsplibReader, AcceptsColonSpacingMissingEofScientificNotationAndAnyNodeOrder) {
  const Instance i = parse(
      "NAME:five\r\nTYPE: TSP\nDIMENSION :5\nEDGE_WEIGHT_TYPE:   CEIL_2D  \n\n"
      "NODE_COORD_SECTION\n 5 6.0e+00 0\n 4 0 8\n3 6 8\n  2   3.00000e+00 4\n1 0 +0\n");
  EXPECT_EQ(i.type(), EdgeWeightType::ceil_2d);
  EXPECT_EQ(i.coords()[4].x, 6.0);
  EXPECT_EQ(i.distance(0, 1), 5.0);
}

TEST(TsplibReader, ReadsTheBundledInstances) {
  for (const char* name : {"eil51", "att532", "pr2392"}) {
    const Instance i = read_instance(testing::data(std::string(name) + ".tsp"));
    EXPECT_EQ(i.name(), name);
  }
  EXPECT_EQ(read_instance(testing::data("att532.tsp")).type(), EdgeWeightType::att);
}

/// A symmetric matrix written in `layout`, as a TSPLIB EXPLICIT file.
std::string explicit_file(const std::vector<std::vector<int>>& w, const std::string& layout) {
  const std::size_t n = w.size();
  std::ostringstream out;
  out << "NAME: m\nTYPE: TSP\nDIMENSION: " << n
      << "\nEDGE_WEIGHT_TYPE: EXPLICIT\nEDGE_WEIGHT_FORMAT: " << layout
      << "\nEDGE_WEIGHT_SECTION\n";
  // Row forms: outer loop over rows r, inner over columns c, entry w[r][c]; column forms: outer
  // over columns, inner over rows. UPPER keeps r < c, LOWER r > c.
  const bool column = layout.find("_COL") != std::string::npos;
  const bool upper = layout.rfind("UPPER", 0) == 0;
  const bool diagonal = layout.find("DIAG") != std::string::npos || layout == "FULL_MATRIX";
  const bool full = layout == "FULL_MATRIX";
  int on_line = 0;
  for (std::size_t outer = 0; outer < n; ++outer)
    for (std::size_t inner = 0; inner < n; ++inner) {
      const std::size_t r = column ? inner : outer, c = column ? outer : inner;
      const bool keep = full || (upper ? r < c : r > c) || (diagonal && r == c);
      if (!keep) continue;
      out << w[r][c] << (++on_line % 7 == 0 ? "\n" : " ");
    }
  out << "\nEOF\n";
  return out.str();
}

TEST(TsplibReader, ReadsEveryExplicitLayout) {
  aco::Rng rng(5);
  const std::size_t n = 9;
  std::vector<std::vector<int>> w(n, std::vector<int>(n, 0));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) w[i][j] = w[j][i] = static_cast<int>(rng.below(1000));
  for (const char* layout :
       {"FULL_MATRIX", "UPPER_ROW", "LOWER_ROW", "UPPER_DIAG_ROW", "LOWER_DIAG_ROW", "UPPER_COL",
        "LOWER_COL", "UPPER_DIAG_COL", "LOWER_DIAG_COL"}) {
    SCOPED_TRACE(layout);
    const Instance i = parse(explicit_file(w, layout));
    EXPECT_EQ(i.type(), EdgeWeightType::explicit_matrix);
    for (std::uint32_t a = 0; a < n; ++a)
      for (std::uint32_t b = 0; b < n; ++b)
        if (a != b) {
          EXPECT_EQ(i.distance(a, b), w[a][b]);
        }
  }
}

TEST(TsplibWriter, RoundTripsCoordinateAndExplicitInstances) {
  const Instance coords = testing::random_instance(40, 3, EdgeWeightType::att, 5000.0);
  const Instance gr17 = read_instance(testing::fixture("gr17.tsp"));
  for (const Instance* original : {&coords, &gr17}) {
    std::ostringstream out;
    write_instance(out, *original);
    const Instance copy = parse(out.str());
    ASSERT_EQ(copy.size(), original->size());
    EXPECT_EQ(copy.type(), original->type());
    for (std::uint32_t a = 0; a < copy.size(); ++a)
      for (std::uint32_t b = 0; b < copy.size(); ++b)
        EXPECT_EQ(copy.distance(a, b), original->distance(a, b));
  }
}

TEST(TsplibReader, ReportsFileLineAndProblem) {
  EXPECT_EQ(error_of("NAME: x\nTYPE: TSP\nEDGE_WEIGHT_TYPE: EUC_2D\nNODE_COORD_SECTION\n1 0 0\n"),
            "x.tsp:4: NODE_COORD_SECTION before DIMENSION");
  EXPECT_EQ(error_of("NAME: x\nTYPE: TSP\nEDGE_WEIGHT_TYPE: EUC_2D\n"), "x.tsp: missing DIMENSION");
  EXPECT_EQ(error_of(kHeader + "NODE_COORD_SECTION\n1 0 0\n2 3 4\n3 6 8\nEOF\n"),
            "x.tsp:9: NODE_COORD_SECTION has 3 of 5 nodes");
  EXPECT_EQ(error_of(kHeader + "NODE_COORD_SECTION\n1 0 0\n2 3 4\n"),
            "x.tsp:7: NODE_COORD_SECTION has 2 of 5 nodes (the file ends)");
  EXPECT_EQ(error_of(kHeader + "NODE_COORD_SECTION\n1 0 0\n2 nan 4\n"),
            "x.tsp:7: node 2 has a non-finite coordinate 'nan'");
  EXPECT_EQ(error_of(kHeader + "NODE_COORD_SECTION\n1 0 0\n2 3 inf\n"),
            "x.tsp:7: node 2 has a non-finite coordinate 'inf'");
  EXPECT_EQ(error_of(kHeader + "NODE_COORD_SECTION\n1 0 0\n2 3 four\n"),
            "x.tsp:7: coordinate 'four' is not a number");
  EXPECT_EQ(error_of(kHeader + "NODE_COORD_SECTION\n1 0 0\n1 3 4\n"),
            "x.tsp:7: node 1 appears twice");
  EXPECT_EQ(error_of(kHeader + "NODE_COORD_SECTION\n1 0 0\n6 3 4\n"),
            "x.tsp:7: node id '6' is not in 1..5");
  EXPECT_EQ(error_of(kHeader + "NODE_COORD_SECTION\n1 0 0 0\n"),
            "x.tsp:6: expected 'id x y' in NODE_COORD_SECTION");
  EXPECT_EQ(error_of("NAME: x\nTYPE: TSP\nDIMENSION: 5\nEDGE_WEIGHT_TYPE: MAN_2D\n"),
            "x.tsp:4: EDGE_WEIGHT_TYPE MAN_2D is not supported (EUC_2D, CEIL_2D, ATT, GEO, "
            "EXPLICIT)");
  EXPECT_EQ(error_of("NAME: x\nTYPE: ATSP\n"), "x.tsp:2: TYPE ATSP is not supported (TSP only)");
  EXPECT_EQ(error_of("NAME: x\nTYPE: TOUR\n"),
            "x.tsp:2: TYPE TOUR: this is a tour file, not an instance");
  EXPECT_EQ(error_of("NAME: x\nDIMENSION: two\n"), "x.tsp:2: DIMENSION 'two' is not an integer");
  EXPECT_EQ(error_of("NAME: x\nDIMENSION: 2\n"),
            "x.tsp:2: DIMENSION 2: a tour needs at least 3 nodes");
  EXPECT_EQ(error_of("NAME: x\nDIMENSION: 5\nDIMENSION: 5\n"), "x.tsp:3: DIMENSION given twice");
  EXPECT_EQ(error_of(kHeader + "WEIGHTS: 3\n"), "x.tsp:5: unknown keyword 'WEIGHTS'");
  EXPECT_EQ(error_of(kHeader + "FIXED_EDGES_SECTION\n1 2\n-1\n"),
            "x.tsp:5: FIXED_EDGES_SECTION is not supported");
  EXPECT_EQ(error_of(kHeader), "x.tsp: missing NODE_COORD_SECTION");
  EXPECT_EQ(error_of("NAME: x\nTYPE: TSP\nDIMENSION: 3\n" + kCoords.substr(0, 0) +
                     "NODE_COORD_SECTION\n1 0 0\n2 1 1\n3 2 2\n"),
            "x.tsp: missing EDGE_WEIGHT_TYPE");
}

TEST(TsplibReader, ReportsMalformedExplicitMatrices) {
  const std::string head = "NAME: m\nTYPE: TSP\nDIMENSION: 3\nEDGE_WEIGHT_TYPE: EXPLICIT\n";
  EXPECT_EQ(error_of(head + "EDGE_WEIGHT_SECTION\n1 2 3\n"),
            "x.tsp:5: EDGE_WEIGHT_SECTION needs an EDGE_WEIGHT_FORMAT matrix layout before it");
  EXPECT_EQ(error_of(head + "EDGE_WEIGHT_FORMAT: TRIANGLE\n"),
            "x.tsp:5: EDGE_WEIGHT_FORMAT TRIANGLE is not supported");
  const std::string upper = head + "EDGE_WEIGHT_FORMAT: UPPER_ROW\nEDGE_WEIGHT_SECTION\n";
  EXPECT_EQ(error_of(upper + "1 2\n"),
            "x.tsp:7: EDGE_WEIGHT_SECTION has 2 of 3 weights (the file ends)");
  EXPECT_EQ(error_of(upper + "1 2\nEOF\n"), "x.tsp:8: EDGE_WEIGHT_SECTION has 2 of 3 weights");
  EXPECT_EQ(error_of(upper + "1 2 3 4\n"), "x.tsp:7: more weights than the 3 expected");
  EXPECT_EQ(error_of(upper + "1 -2 3\n"),
            "x.tsp:7: weight '-2' is not a non-negative 32-bit integer");
  EXPECT_EQ(error_of(upper + "1 2.5 3\n"),
            "x.tsp:7: weight '2.5' is not a non-negative 32-bit integer");
  EXPECT_EQ(error_of(upper + "1 nan 3\n"),
            "x.tsp:7: weight 'nan' is not a non-negative 32-bit integer");
  EXPECT_EQ(error_of(head + "EDGE_WEIGHT_FORMAT: FULL_MATRIX\nEDGE_WEIGHT_SECTION\n0 1 2\n1 0 "
                            "3\n2 4 0\n"),
            "x.tsp: weight matrix is not symmetric between nodes 2 and 3 (only the symmetric "
            "TSP is supported)");
  EXPECT_EQ(error_of(head + "EDGE_WEIGHT_FORMAT: UPPER_ROW\n"),
            "x.tsp: missing EDGE_WEIGHT_SECTION");
}

TEST(TsplibReader, ReportsAMissingFile) {
  EXPECT_THROW(
      {
        try {
          read_instance("/nonexistent/dir/x.tsp");
        } catch (const std::runtime_error& e) {
          EXPECT_STREQ(e.what(), "/nonexistent/dir/x.tsp: cannot open");
          throw;
        }
      },
      std::runtime_error);
}

TEST(TsplibReader, RejectsBadGeoCoordinates) {
  EXPECT_THAT(error_of("NAME: g\nTYPE: TSP\nDIMENSION: 3\nEDGE_WEIGHT_TYPE: GEO\n"
                       "NODE_COORD_SECTION\n1 10 10\n2 95.0 10\n3 0 0\n"),
              HasSubstr("x.tsp: node 2: GEO coordinates must be latitude/longitude"));
}

TEST(Generator, IsSeededAndInRange) {
  const Instance a = random_uniform_instance(500, 7, 1000.0);
  const Instance b = random_uniform_instance(500, 7, 1000.0);
  const Instance c = random_uniform_instance(500, 8, 1000.0);
  EXPECT_EQ(a.name(), "E500.s7");
  bool differs = false;
  for (std::size_t i = 0; i < 500; ++i) {
    EXPECT_EQ(a.coords()[i].x, b.coords()[i].x);
    EXPECT_EQ(a.coords()[i].y, b.coords()[i].y);
    EXPECT_GE(a.coords()[i].x, 0.0);
    EXPECT_LE(a.coords()[i].y, 1000.0);
    EXPECT_EQ(a.coords()[i].x, std::floor(a.coords()[i].x));
    differs = differs || a.coords()[i].x != c.coords()[i].x;
  }
  EXPECT_TRUE(differs);
  EXPECT_THROW(random_uniform_instance(2, 1), std::invalid_argument);
  EXPECT_THROW(random_uniform_instance(10, 1, 0.5), std::invalid_argument);
}

TEST(Generator, ClusteredIsSeededInRangeAndClustered) {
  const Instance a = random_clustered_instance(2000, 3);
  const Instance b = random_clustered_instance(2000, 3);
  EXPECT_EQ(a.name(), "C2000.s3");
  for (std::size_t i = 0; i < 2000; ++i) {
    EXPECT_EQ(a.coords()[i].x, b.coords()[i].x);
    EXPECT_EQ(a.coords()[i].y, b.coords()[i].y);
    EXPECT_GE(a.coords()[i].x, 0.0);
    EXPECT_LE(a.coords()[i].y, 1.0e6);
    EXPECT_EQ(a.coords()[i].y, std::floor(a.coords()[i].y));
  }
  // Clustered cities are closer to their nearest neighbour than uniform ones: the mean
  // nearest-neighbour distance of a uniform instance is about 0.5 side / sqrt(n) = 11180 here
  // (plus a boundary effect); DIMACS's 200 clusters of standard deviation side / sqrt(n) are
  // only about 1.6 times as dense, clusters of a fifth of that spread 25 times.
  const auto mean_nearest = [](const Instance& instance) {
    double total = 0.0;
    for (std::uint32_t i = 0; i < instance.size(); ++i) {
      double best = 1e300;
      for (std::uint32_t j = 0; j < instance.size(); ++j)
        if (j != i) best = std::min(best, instance.distance(i, j));
      total += best;
    }
    return total / static_cast<double>(instance.size());
  };
  const double uniform = mean_nearest(random_uniform_instance(2000, 3));
  EXPECT_NEAR(uniform, 11180.0, 1000.0);
  EXPECT_LT(mean_nearest(a), 0.95 * uniform);
  EXPECT_LT(mean_nearest(random_clustered_instance(2000, 3, 1e6, {.spread = 0.2})), 0.3 * uniform);
  EXPECT_THROW(random_clustered_instance(2, 1), std::invalid_argument);
  EXPECT_THROW(random_clustered_instance(100, 1, 1e6, {.spread = 0.0}), std::invalid_argument);
}

}  // namespace
}  // namespace antslam::tsp
