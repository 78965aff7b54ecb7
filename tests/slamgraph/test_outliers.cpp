// False loop closures (the Vertigo protocol): where they go, their measurements, groups, seeds,
// and the list that marks them in a graph.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "antslam/slamgraph/outliers.hpp"
#include "pose_graphs.hpp"
#include "support.hpp"

namespace antslam::slam {
namespace {

const testing::TrueGraph& base() {
  static const testing::TrueGraph t = testing::square_laps(3, 10, 5, 0.02, 3);
  return t;
}

TEST(Outliers, AppendedAfterTheGraphsOwnEdges) {
  const SpoiledGraph s = add_outliers(base().graph, {.count = 50, .seed = 4});
  const std::size_t own = base().graph.edges.size();
  ASSERT_EQ(s.graph.edges.size(), own + 50);
  ASSERT_EQ(s.outliers.size(), 50U);
  for (std::size_t e = 0; e < own; ++e)
    EXPECT_EQ(s.graph.edges[e].measurement.x, base().graph.edges[e].measurement.x);
  double sum_x = 0.0, sum_xx = 0.0;
  for (std::size_t k = 0; k < 50; ++k) {
    const PoseGraphEdge& e = s.graph.edges[own + k];
    EXPECT_EQ(std::pair(e.from, e.to), s.outliers[k]);
    EXPECT_LT(e.from + 1, e.to);  // never consecutive (that would be odometry), v1 < v2
    EXPECT_LT(e.to, base().graph.vertices.size());
    EXPECT_TRUE(e.information.isApprox(42.7 * Eigen::Matrix3d::Identity()));
    sum_x += e.measurement.x;
    sum_xx += e.measurement.x * e.measurement.x;
  }
  EXPECT_NEAR(sum_x / 50, 0.0, 0.15);  // N(0, 0.3): mean within 3.5 sigma/sqrt(50)
  EXPECT_NEAR(std::sqrt(sum_xx / 50), 0.3, 0.1);
}

TEST(Outliers, LocalOnesStayWithinTheWindow) {
  const SpoiledGraph s = add_outliers(base().graph, {.count = 200, .kind = OutlierKind::local});
  for (const auto& [v1, v2] : s.outliers) {
    EXPECT_GE(v2, v1 + 2);
    EXPECT_LE(v2, v1 + 20);
  }
}

TEST(Outliers, GroupsShareOneMeasurementOnConsecutiveVertices) {
  const SpoiledGraph s = add_outliers(
      base().graph, {.count = 23, .kind = OutlierKind::random_group, .group_size = 10, .seed = 2});
  const std::size_t own = base().graph.edges.size();
  ASSERT_EQ(s.outliers.size(), 23U);  // groups of 10, 10 and 3
  for (std::size_t k = 0; k < 23; ++k) {
    const std::size_t first = own + k / 10 * 10;
    const PoseGraphEdge& e = s.graph.edges[own + k];
    EXPECT_EQ(e.from, s.graph.edges[first].from + k % 10);
    EXPECT_EQ(e.to, s.graph.edges[first].to + k % 10);
    EXPECT_EQ(e.measurement.theta, s.graph.edges[first].measurement.theta);
  }
  EXPECT_NE(s.graph.edges[own].measurement.x, s.graph.edges[own + 10].measurement.x);
}

TEST(Outliers, SameSeedSameClosuresOtherSeedOthers) {
  const OutlierSettings a{.count = 30, .kind = OutlierKind::local_group, .group_size = 5};
  OutlierSettings b = a;
  b.seed = 2;
  EXPECT_EQ(add_outliers(base().graph, a).outliers, add_outliers(base().graph, a).outliers);
  EXPECT_NE(add_outliers(base().graph, a).outliers, add_outliers(base().graph, b).outliers);
}

TEST(Outliers, RejectsGraphsTooSmallAndNonsenseSettings) {
  PoseGraph tiny = base().graph;
  tiny.vertices.resize(12);
  tiny.edges.clear();
  EXPECT_THROW(add_outliers(tiny, {.kind = OutlierKind::random_group, .group_size = 10}),
               std::invalid_argument);
  EXPECT_NO_THROW(add_outliers(tiny, {.count = 5}));
  EXPECT_THROW(add_outliers(base().graph, {.kind = OutlierKind::random_group, .group_size = 0}),
               std::invalid_argument);
  EXPECT_THROW(add_outliers(base().graph, {.sigma_xy = std::nan("")}), std::invalid_argument);
  EXPECT_THROW(add_outliers(base().graph, {.information = 0.0}), std::invalid_argument);
}

TEST(Outliers, KindNamesRoundTrip) {
  for (const OutlierKindInfo& k : kOutlierKinds) EXPECT_EQ(parse_outlier_kind(k.name), k.value);
  EXPECT_FALSE(parse_outlier_kind("bogus"));
  EXPECT_EQ(outliers_path_of("dir/x.g2o"), std::filesystem::path("dir/x.outliers.txt"));
}

std::filesystem::path write_list(const std::string& name, const std::string& text) {
  std::filesystem::create_directories(ANTSLAM_TEST_TMP);
  const std::filesystem::path path = std::filesystem::path(ANTSLAM_TEST_TMP) / name;
  std::ofstream(path) << text;
  return path;
}

TEST(Outliers, TheListMarksTheAppendedClosuresEvenOverATrueOne) {
  // A false closure on the vertices of a true one: the appended (last) one is marked.
  const PoseGraph& g = base().graph;
  SpoiledGraph s = add_outliers(g, {.count = 20, .seed = 9});
  const ChainSplit own = split_chain(g, "own");
  const PoseGraphEdge& first_true = g.edges[own.closures[0]];
  s.graph.edges.push_back({first_true.to, first_true.from, Pose2{}, first_true.information});
  s.outliers.emplace_back(first_true.from, first_true.to);
  std::ostringstream list;
  write_outlier_pairs(list, s.outliers);
  const ChainSplit split = split_chain(s.graph, "spoiled");
  const std::vector<bool> flags =
      read_outlier_flags(write_list("list.txt", "# false\n" + list.str()), s.graph, split);
  ASSERT_EQ(flags.size(), split.closures.size());
  for (std::size_t k = 0; k < flags.size(); ++k)
    EXPECT_EQ(flags[k], k >= own.closures.size()) << "closure " << k;
}

TEST(Outliers, TheListRejectsMalformedLinesAndUnknownPairs) {
  const PoseGraph& g = base().graph;
  const ChainSplit split = split_chain(g, "g");
  const auto error = [&](const std::string& text) {
    const auto path = write_list("bad.txt", text);
    return testing::error_of([&] { read_outlier_flags(path, g, split); });
  };
  const std::string path = (std::filesystem::path(ANTSLAM_TEST_TMP) / "bad.txt").string();
  EXPECT_EQ(error("1 2 3\n"), path + ":1: expected `i j`");
  EXPECT_EQ(error("\n4 x\n"), path + ":2: 'x' is not a vertex id");
  EXPECT_EQ(error("0 1\n"),
            path + ":1: 0 1 is not a loop closure of the graph (or is listed more often)");
  EXPECT_EQ(testing::error_of([&] { read_outlier_flags("missing.txt", g, split); }),
            "missing.txt: cannot open");
}

}  // namespace
}  // namespace antslam::slam
