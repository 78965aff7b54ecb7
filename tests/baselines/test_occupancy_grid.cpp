#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>

#include "antslam/aco/random.hpp"
#include "antslam/baselines/occupancy_grid.hpp"

namespace antslam::baselines {
namespace {

using V = Eigen::Vector2d;

TEST(OccupancyGrid, CellUpdateIsEquationOne) {
  OccupancyGrid grid(0.05);
  EXPECT_FLOAT_EQ(grid.at(3, -7), 0.5F);  // never written: unknown
  grid.update(3, -7, 0.2, 1.0);           // 0.8 * 0.5 + 0.2 * 1
  EXPECT_FLOAT_EQ(grid.at(3, -7), 0.6F);
  grid.update(3, -7, 0.2, 0.0);  // 0.8 * 0.6
  EXPECT_FLOAT_EQ(grid.at(3, -7), 0.48F);
  EXPECT_FLOAT_EQ(grid.at(V(0.175, -0.325)), 0.48F);  // the centre of cell (3, -7)
  EXPECT_FLOAT_EQ(grid.at(4, -7), 0.5F);
}

TEST(OccupancyGrid, GrowingKeepsTheCells) {
  OccupancyGrid grid(0.1);
  grid.update(0, 0, 1.0, 1.0);
  grid.update(-500, 300, 1.0, 0.0);  // far away: the grid grows in both directions
  grid.update(700, -20, 1.0, 1.0);
  EXPECT_FLOAT_EQ(grid.at(0, 0), 1.0F);
  EXPECT_FLOAT_EQ(grid.at(-500, 300), 0.0F);
  EXPECT_FLOAT_EQ(grid.at(700, -20), 1.0F);
  EXPECT_FLOAT_EQ(grid.at(1, 0), 0.5F);
  EXPECT_LE(grid.min_x(), -500);
  EXPECT_GE(grid.min_x() + grid.width() - 1, 700);
}

TEST(OccupancyGrid, RefusesToGrowBeyondItsLimit) {
  OccupancyGrid grid(0.05, 1000);
  grid.update(0, 0, 1.0, 1.0);
  EXPECT_THROW(grid.update(2000, 2000, 1.0, 1.0), std::runtime_error);
  EXPECT_THROW(OccupancyGrid(0.0), std::invalid_argument);
}

TEST(OccupancyGrid, BeamValuesAreTheBlurredProfileByHand) {
  // Origin and hit at cell centres on row 0, 5 cm cells, hole width 0.2 m, q = 1 (the cell takes
  // the value): value = max(0, 1 - |s - r| / 0.1) with s = 0.05 i and r = 1.0 (cell 20).
  OccupancyGrid grid(0.05);
  grid.insert_beam(V(0.025, 0.025), V(1.025, 0.025), 1.0, 0.2);
  for (int i = 0; i <= 18; ++i) EXPECT_NEAR(grid.at(i, 0), 0.0F, 1e-6) << i;
  EXPECT_NEAR(grid.at(19, 0), 0.5F, 1e-6);
  EXPECT_FLOAT_EQ(grid.at(20, 0), 1.0F);
  EXPECT_NEAR(grid.at(21, 0), 0.5F, 1e-6);
  EXPECT_NEAR(grid.at(22, 0), 0.0F, 1e-6);  // the beam ends half a hole behind the hit
  EXPECT_FLOAT_EQ(grid.at(23, 0), 0.5F);    // untouched
  EXPECT_FLOAT_EQ(grid.at(10, 1), 0.5F);
  EXPECT_FLOAT_EQ(grid.at(-1, 0), 0.5F);
}

/// Whether the segment a-b runs through the square cell (x, y) over a positive length
/// (Liang-Barsky clipping).
bool crosses(const V& a, const V& b, std::int64_t x, std::int64_t y, double h) {
  double t0 = 0.0, t1 = 1.0;
  const V d = b - a;
  const double lo[2] = {static_cast<double>(x) * h, static_cast<double>(y) * h};
  for (int axis = 0; axis < 2; ++axis) {
    const double p = a[axis], q = d[axis];
    if (q == 0.0) {
      if (p < lo[axis] || p >= lo[axis] + h) return false;
      continue;
    }
    double ta = (lo[axis] - p) / q, tb = (lo[axis] + h - p) / q;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t1 - t0 > 1e-9;
}

TEST(OccupancyGrid, BeamVisitsExactlyTheCellsItCrosses) {
  // Against brute force over the cells around random segments. With q = 1 and no hole, a
  // visited cell becomes 0 (1 at the hit) and the others stay 0.5.
  aco::Rng rng(11);
  const double h = 0.1;
  for (int trial = 0; trial < 300; ++trial) {
    const V a(4.0 * rng.uniform() - 2.0, 4.0 * rng.uniform() - 2.0);
    const V b(4.0 * rng.uniform() - 2.0, 4.0 * rng.uniform() - 2.0);
    OccupancyGrid grid(h);
    grid.update(-25, -25, 1.0, 0.5);  // cover the whole square first
    grid.update(25, 25, 1.0, 0.5);
    grid.insert_beam(a, b, 1.0, 0.0);
    for (std::int64_t y = -25; y <= 25; ++y)
      for (std::int64_t x = -25; x <= 25; ++x)
        EXPECT_EQ(grid.at(x, y) != 0.5F, crosses(a, b, x, y, h))
            << "trial " << trial << " cell " << x << ", " << y;
    EXPECT_FLOAT_EQ(grid.at(b), 1.0F);
  }
}

}  // namespace
}  // namespace antslam::baselines
