// The QAPLIB reader: the bundled instances, a write-read round trip, and one error line naming
// the file, the line and the problem for each kind of bad input.

#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>
#include <string>

#include "antslam/qap/qaplib.hpp"
#include "qap_test_support.hpp"

namespace antslam::qap {
namespace {

Instance parse(const std::string& text) {
  std::istringstream in(text);
  return parse_qaplib(in, "bad.dat");
}

/// The message parse(text) throws.
std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "no error";
}

TEST(QaplibReader, ReadsTheBundledInstances) {
  const Instance chr12a = read_qaplib(testing::data("chr12a.dat"));
  EXPECT_EQ(chr12a.name(), "chr12a");
  ASSERT_EQ(chr12a.size(), 12U);
  EXPECT_EQ(chr12a.flow(0, 1), 90);  // the first rows of the file
  EXPECT_EQ(chr12a.flow(1, 5), 88);
  EXPECT_EQ(chr12a.distance(0, 1), 36);
  EXPECT_EQ(chr12a.distance(11, 11), 0);
  EXPECT_EQ(chr12a.distance(11, 10), 18);  // the last row of the file
  for (const char* name : {"nug12.dat", "tai12a.dat"})
    EXPECT_EQ(read_qaplib(testing::data(name)).size(), 12U);
}

TEST(QaplibReader, RoundTrip) {
  const Instance original = read_qaplib(testing::data("tai12a.dat"));
  std::ostringstream written;
  write_qaplib(written, original);
  std::istringstream in(written.str());
  const Instance back = parse_qaplib(in, "written");
  ASSERT_EQ(back.size(), original.size());
  EXPECT_TRUE(std::ranges::equal(back.flows(), original.flows()));
  EXPECT_TRUE(std::ranges::equal(back.distances(), original.distances()));
  std::ostringstream again;
  write_qaplib(again, back);
  EXPECT_EQ(again.str(), written.str());
}

TEST(QaplibReader, FreeWhitespaceBlankLinesAndCrlf) {
  const Instance i = parse("\r\n 2 \r\n\r\n0\t3\n\n\n4 0\r\n0 5 6\n 0\n\n");
  EXPECT_EQ(i.flow(0, 1), 3);
  EXPECT_EQ(i.flow(1, 0), 4);
  EXPECT_EQ(i.distance(0, 1), 5);
  EXPECT_EQ(i.distance(1, 0), 6);
}

TEST(QaplibReader, EachBadInputNamesItsLine) {
  EXPECT_EQ(error_of(""), "bad.dat:1: no size n: the file is empty");
  EXPECT_EQ(error_of("\n\ntwelve\n"), "bad.dat:3: size n 'twelve' is not an integer");
  EXPECT_EQ(error_of("-3\n"), "bad.dat:1: size n -3 is negative");
  EXPECT_EQ(error_of("0\n"), "bad.dat:1: size n is 0: a QAP needs at least one facility");
  EXPECT_EQ(error_of("5000\n"), "bad.dat:1: size n 5000 is larger than 2048");
  EXPECT_EQ(error_of("2\n0 1\n1 0\n\n0 5\n"),
            "bad.dat:5: matrix B has 2 of 4 numbers (the file ends)");
  EXPECT_EQ(error_of("2\n0 1\n"), "bad.dat:2: matrix A has 2 of 4 numbers (the file ends)");
  EXPECT_EQ(error_of("2\n0 1.5\n1 0\n"), "bad.dat:2: entry (1, 2) of A '1.5' is not an integer");
  EXPECT_EQ(error_of("2\n0 1\n1 0\n0 2\n3x 0\n"),
            "bad.dat:5: entry (2, 1) of B '3x' is not an integer");
  EXPECT_EQ(error_of("2\n0 1\n1 0\n0 2\n-4 0\n"),
            "bad.dat:5: entry (2, 1) of B is negative (-4): costs must be >= 0");
  EXPECT_EQ(error_of("2\n0 99999999999999999999\n"),
            "bad.dat:2: entry (1, 2) of A '99999999999999999999' is not an integer");
  EXPECT_EQ(error_of("2\n0 1\n1 0\n0 2\n2 0\n\n7\n"),
            "bad.dat:7: trailing text '7' after the two matrices");
  // n^2 max A max B = 4 * 2^60 * 2 = 2^63: a cost could overflow.
  EXPECT_EQ(error_of("2\n0 1152921504606846976\n0 0\n0 1\n2 0\n"),
            "bad.dat:5: entry (2, 1) of B 2: costs can exceed 64-bit integers "
            "(n^2 max A max B > 2^63 - 1)");
  EXPECT_NO_THROW(parse("2\n0 1152921504606846976\n0 0\n0 1\n1 0\n"));
  EXPECT_EQ(error_of("2\n0 2305843009213693952\n"),
            "bad.dat:2: entry (1, 2) of A 2305843009213693952: costs can exceed 64-bit "
            "integers (n^2 max A max B > 2^63 - 1)");
}

TEST(QaplibReader, MissingFile) {
  EXPECT_THROW(
      {
        try {
          read_qaplib(testing::data("none.dat"));
        } catch (const std::runtime_error& e) {
          EXPECT_NE(std::string(e.what()).find("none.dat: cannot open"), std::string::npos);
          throw;
        }
      },
      std::runtime_error);
}

}  // namespace
}  // namespace antslam::qap
