#include <gtest/gtest.h>

#include <vector>

#include "antslam/aco/edge_trail.hpp"
#include "antslam/aco/layered_trail.hpp"

namespace antslam::aco {
namespace {

TEST(LayeredTrail, EvaporateDepositClamp) {
  const std::vector<std::size_t> counts{3, 2};
  LayeredTrail trail(counts);
  trail.fill(10.0);
  trail.evaporate(0.1);
  const std::vector<std::uint32_t> path{2, 0};
  trail.deposit(path, 5.0);
  EXPECT_DOUBLE_EQ(trail.at(0, 2), 14.0);
  EXPECT_DOUBLE_EQ(trail.at(0, 0), 9.0);
  EXPECT_DOUBLE_EQ(trail.at(1, 0), 14.0);
  EXPECT_DOUBLE_EQ(trail.at(1, 1), 9.0);
  trail.clamp(9.5, 12.0);
  EXPECT_DOUBLE_EQ(trail.min_value(), 9.5);
  EXPECT_DOUBLE_EQ(trail.max_value(), 12.0);
}

TEST(LayeredTrail, BranchingFactorCountsStrongOptions) {
  const std::vector<std::size_t> counts{4, 4};
  LayeredTrail trail(counts);
  trail.fill(1.0);
  EXPECT_DOUBLE_EQ(trail.branching_factor(0.05), 4.0);  // undecided: every option counts
  trail.at(0, 1) = 100.0;
  trail.at(1, 2) = 100.0;
  trail.at(1, 3) = 100.0;
  EXPECT_DOUBLE_EQ(trail.branching_factor(0.05), 1.5);
}

TEST(LayeredTrail, RejectsEmptyLayer) {
  const std::vector<std::size_t> counts{3, 0};
  EXPECT_THROW(LayeredTrail{counts}, std::invalid_argument);
}

// Square 0-1-2-3 with candidate lists of 2 (its two neighbours on the square), plus the
// diagonal 0-2 in 0's list only.
EdgeTrail square_trail() { return EdgeTrail(4, 2, {1, 2, /*1:*/ 0, 2, /*2:*/ 1, 3, /*3:*/ 2, 0}); }

TEST(EdgeTrail, SymmetricCopiesStayEqual) {
  EdgeTrail trail = square_trail();
  trail.fill(1.0);
  const std::vector<std::uint32_t> tour{0, 1, 2, 3};
  trail.deposit(tour, 2.0);
  EXPECT_DOUBLE_EQ(trail.edge(0, 1), 3.0);
  EXPECT_DOUBLE_EQ(trail.edge(1, 0), 3.0);
  EXPECT_DOUBLE_EQ(trail.edge(2, 3), 3.0);
  EXPECT_DOUBLE_EQ(trail.edge(3, 0), 3.0);
  EXPECT_DOUBLE_EQ(trail.edge(0, 2), 1.0);  // diagonal, not in the tour
  for (std::uint32_t i = 0; i < 4; ++i)
    for (std::uint32_t j = 0; j < 4; ++j) {
      if (i == j) continue;
      EXPECT_DOUBLE_EQ(trail.edge(i, j), trail.edge(j, i)) << i << "-" << j;
    }
}

TEST(EdgeTrail, NonCandidateEdgeCarriesNothing) {
  EdgeTrail trail = square_trail();
  trail.fill(1.0);
  EXPECT_DOUBLE_EQ(trail.edge(1, 3), 0.0);
  EXPECT_EQ(trail.update_edge(1, 3, [](double& t) { t += 1.0; }), EdgeTrail::kNone);
}

TEST(EdgeTrail, ConvergedTourHasBranchingTwo) {
  EdgeTrail trail(4, 3, {1, 2, 3, 0, 2, 3, 1, 3, 0, 2, 0, 1});
  trail.fill(0.01);
  trail.deposit(std::vector<std::uint32_t>{0, 1, 2, 3}, 10.0);
  EXPECT_DOUBLE_EQ(trail.branching_factor(0.05), 2.0);
}

}  // namespace
}  // namespace antslam::aco
