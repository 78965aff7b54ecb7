// Pose graphs as they are found in the public benchmark sets: files without vertices, several
// sessions, TORO lines, FIX lines, 3D types, each shape in a small file with hand-computed poses.

#include <gtest/gtest.h>

#include <numbers>
#include <sstream>

#include "antslam/slamgraph/g2o.hpp"
#include "antslam/slamgraph/graph_structure.hpp"
#include "support.hpp"

namespace antslam::slam {
namespace {

constexpr double kHalfPi = std::numbers::pi / 2.0;

PoseGraph parse(const std::string& text) {
  std::istringstream in(text);
  return read_g2o(in, "graph.g2o");
}

std::string error_of(const std::string& text) {
  return testing::error_of([&] { parse(text); });
}

void expect_pose(const Pose2& p, double x, double y, double theta) {
  EXPECT_NEAR(p.x, x, 1e-12);
  EXPECT_NEAR(p.y, y, 1e-12);
  EXPECT_NEAR(wrap_angle(p.theta - theta), 0.0, 1e-12);
}

// SE-Sync's files: edges only. The poses chain the odometry: three unit steps, each turning
// left by 90 degrees, walk three sides of a unit square; the edge 3 -> 2 is stored backwards.
TEST(G2oWithoutVertices, ChainsTheOdometryEdges) {
  const PoseGraph g = parse(
      "EDGE_SE2 0 1 1 0 1.5707963267948966 1 0 0 1 0 1\n"
      "EDGE_SE2 1 2 1 0 1.5707963267948966 1 0 0 1 0 1\n"
      "EDGE_SE2 3 2 0 1 -1.5707963267948966 1 0 0 1 0 1\n"  // pose of 2 in 3's frame
      "EDGE_SE2 3 0 3 0 1.5707963267948966 1 0 0 1 0 1\n");
  EXPECT_FALSE(g.vertices_from_file);
  ASSERT_EQ(g.vertices.size(), 4U);
  expect_pose(g.vertices[0], 0, 0, 0);
  expect_pose(g.vertices[1], 1, 0, kHalfPi);
  expect_pose(g.vertices[2], 1, 1, std::numbers::pi);
  // X_3 = X_2 (0, 1, -pi/2)^-1 = (1, 1, pi) (1, 0, pi/2) = (0, 1, -pi/2).
  expect_pose(g.vertices[3], 0, 1, -kHalfPi);
  // The loop closure 3 -> 0 was not used: it says (3, 0, pi/2) where the chain has (1, 0, pi/2).
  EXPECT_NEAR(score(g, g.vertices).chi2, 4.0, 1e-12);
}

// Two sessions (0-1-2 and 3-4-5) joined only by a closure 1 -> 4: the second session is entered
// through that closure, and its other vertices follow its odometry from there.
TEST(G2oWithoutVertices, EntersEachSessionThroughAClosure) {
  const PoseGraph g = parse(
      "EDGE_SE2 0 1 1 0 0 1 0 0 1 0 1\n"
      "EDGE_SE2 1 2 1 0 0 1 0 0 1 0 1\n"
      "EDGE_SE2 3 4 0 2 0 1 0 0 1 0 1\n"
      "EDGE_SE2 4 5 0 2 0 1 0 0 1 0 1\n"
      "EDGE_SE2 1 4 0 5 1.5707963267948966 1 0 0 1 0 1\n");
  ASSERT_EQ(g.vertices.size(), 6U);
  expect_pose(g.vertices[2], 2, 0, 0);
  expect_pose(g.vertices[4], 1, 5, kHalfPi);
  expect_pose(g.vertices[5], -1, 5, kHalfPi);
  expect_pose(g.vertices[3], 3, 5, kHalfPi);
  // Every edge but the closure is then exact.
  EXPECT_NEAR(score(g, g.vertices).chi2, 0.0, 1e-20);
}

TEST(G2oWithoutVertices, RefusesGapsAndSeparateParts) {
  EXPECT_EQ(error_of("EDGE_SE2 0 2 1 0 0 1 0 0 1 0 1\n"),
            "graph.g2o: no vertex lines, and vertex 1 is in no edge (ids must be 0..n-1)");
  EXPECT_EQ(error_of("EDGE_SE2 0 1 1 0 0 1 0 0 1 0 1\nEDGE_SE2 2 3 1 0 0 1 0 0 1 0 1\n"),
            "graph.g2o: vertex 2 is joined to vertex 0 by no chain of edges, so it has no "
            "initial pose (the file has no vertex lines)");
  EXPECT_EQ(error_of("# nothing\n"), "graph.g2o: no vertices or edges");
}

// TORO's 2D lines: the information in the order xx, xy, yy, tt, xt, yt.
TEST(Toro, ReadsItsOrderOfTheInformationAndWritesItBack) {
  const PoseGraph g = parse(
      "VERTEX2 0 0 0 0\nVERTEX2 1 1 0.5 0.1\n"
      "EDGE2 0 1 1 0.5 0 10 1 20 30 2 3\n");
  ASSERT_EQ(g.edges.size(), 1U);
  Eigen::Matrix3d expected;
  expected << 10, 1, 2, 1, 20, 3, 2, 3, 30;
  EXPECT_EQ(g.edges[0].information, expected);
  EXPECT_EQ(g.vertices[1].y, 0.5);
  std::ostringstream toro;
  write_toro(toro, g);
  EXPECT_NE(toro.str().find("EDGE2 0 1 1 0.5 0 10 1 20 30 2 3\n"), std::string::npos);
  const PoseGraph back = parse(toro.str());
  EXPECT_EQ(back.edges[0].information, expected);
  // The same graph in g2o's order reads the same.
  std::ostringstream g2o;
  write_pose_graph(g2o, g, "out.g2o");
  EXPECT_NE(g2o.str().find("EDGE_SE2 0 1 1 0.5 0 10 1 2 20 3 30\n"), std::string::npos);
  EXPECT_EQ(parse(g2o.str()).edges[0].information, expected);
  EXPECT_TRUE(is_pose_graph_file("x.graph"));
  EXPECT_TRUE(is_pose_graph_file("x.g2o"));
  EXPECT_FALSE(is_pose_graph_file("x.json"));
}

TEST(Fix, HoldsTheNamedVerticesAndRoundTrips) {
  const std::string text =
      "VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 0\nVERTEX_SE2 2 2 0 0\n"
      "FIX 2\nFIX 1 2\n"
      "EDGE_SE2 0 1 1 0 0 1 0 0 1 0 1\nEDGE_SE2 1 2 1 0 0 1 0 0 1 0 1\n";
  const PoseGraph g = parse(text);
  EXPECT_EQ(g.fixed, (std::vector<std::size_t>{1, 2}));
  EXPECT_EQ(fixed_vertices(g), g.fixed);
  std::ostringstream out;
  write_g2o(out, g);
  EXPECT_NE(out.str().find("FIX 1\nFIX 2\n"), std::string::npos);
  EXPECT_EQ(parse(out.str()).fixed, g.fixed);
  // Without FIX lines vertex 0 is held.
  EXPECT_EQ(fixed_vertices(parse("VERTEX_SE2 0 0 0 0\n")), std::vector<std::size_t>{0});
}

TEST(Fix, RefusesWhatIsNotAVertex) {
  const std::string two = "VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 0\n";
  EXPECT_EQ(error_of(two + "FIX banana 1e400\n"), "graph.g2o:3: 'banana' is not a vertex id");
  EXPECT_EQ(error_of(two + "FIX 1e400\n"), "graph.g2o:3: '1e400' is not a vertex id");
  EXPECT_EQ(error_of(two + "FIX\n"), "graph.g2o:3: '' is not a vertex id");
  EXPECT_EQ(error_of(two + "FIX 0 7\n"), "graph.g2o:3: FIX of undefined vertex 7");
}

TEST(G2oTags, RefusesThreeDimensionalTypesByName) {
  const std::string expected =
      "is a 3D type; antslam reads 2D pose graphs (VERTEX_SE2, EDGE_SE2, VERTEX2, EDGE2 or FIX)";
  EXPECT_EQ(error_of("VERTEX_SE3:QUAT 0 0 0 0 0 0 0 1\n"),
            "graph.g2o:1: 'VERTEX_SE3:QUAT' " + expected);
  EXPECT_EQ(error_of("VERTEX_SE2 0 0 0 0\nEDGE_SE3:QUAT 0 1 0 0 0 0 0 0 1\n"),
            "graph.g2o:2: 'EDGE_SE3:QUAT' " + expected);
  EXPECT_EQ(error_of("VERTEX3 0 0 0 0 0 0 0\n"), "graph.g2o:1: 'VERTEX3' " + expected);
  EXPECT_EQ(error_of("EDGE3 0 1 0 0 0 0 0 0\n"), "graph.g2o:1: 'EDGE3' " + expected);
  EXPECT_EQ(error_of("VERTEX_XY 0 1 2\n"),
            "graph.g2o:1: unsupported tag 'VERTEX_XY' (expected VERTEX_SE2, EDGE_SE2, VERTEX2, "
            "EDGE2 or FIX)");
}

}  // namespace
}  // namespace antslam::slam
