#pragma once
// The map of the tinySLAM baseline (second paper, Sec. II-A; Steux and El Hamzaoui 2010): a grid
// of cell occupancy probabilities, each updated by eq. (1),
//   map_{n+1}(x, y) = (1 - q) map_n(x, y) + q value,
// where value is what a laser beam says about the cell (1: the beam stops there, 0: it passes).
// tinySLAM blurs the obstacles: the values along a beam fall from 1 at the hit to 0 at half the
// "hole width" before it and behind it, which gives its Monte-Carlo matcher a slope to climb.
// The grid grows as the robot explores; cells never written read as 0.5 (unknown).

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace antslam::baselines {

class OccupancyGrid {
 public:
  /// resolution: metres per cell (> 0); max_cells: refuse to grow beyond (a lost robot would
  /// otherwise allocate without bound).
  explicit OccupancyGrid(double resolution, std::size_t max_cells = 50'000'000);

  double resolution() const { return resolution_; }
  /// The cell holding a point (cell (i, j) covers [i h, (i + 1) h) x [j h, (j + 1) h)).
  std::int64_t cell(double coordinate) const;
  /// Occupancy of a cell, 0.5 if it was never written.
  float at(std::int64_t x, std::int64_t y) const;
  float at(const Eigen::Vector2d& p) const { return at(cell(p.x()), cell(p.y())); }

  /// Eq. (1) on one cell: m <- (1 - q) m + q value, q and value in [0, 1].
  void update(std::int64_t x, std::int64_t y, double quality, double value);

  /// One beam from `origin` that hit at `hit` (metres, map frame): every cell the segment
  /// origin -> hit + hole_width / 2 crosses is updated by eq. (1) with the blurred value
  /// max(0, 1 - |s - r| / (hole_width / 2)) (s: distance of the cell centre along the beam, r:
  /// the range), i.e. 0 in free space, 1 at the hit.
  void insert_beam(const Eigen::Vector2d& origin, const Eigen::Vector2d& hit, double quality,
                   double hole_width);

  /// Grows the grid to hold every cell of the box (inclusive cell bounds).
  void cover(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1);

  bool empty() const { return cells_.empty(); }
  std::int64_t min_x() const { return x0_; }
  std::int64_t min_y() const { return y0_; }
  std::int64_t width() const { return width_; }
  std::int64_t height() const { return height_; }

 private:
  double resolution_;
  std::size_t max_cells_;
  std::int64_t x0_ = 0, y0_ = 0, width_ = 0, height_ = 0;
  std::vector<float> cells_;  ///< row-major, (y - y0) * width + (x - x0)
};

}  // namespace antslam::baselines
