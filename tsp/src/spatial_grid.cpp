#include "antslam/tsp/spatial_grid.hpp"

#include <cmath>
#include <stdexcept>

namespace antslam::tsp {

SpatialGrid::SpatialGrid(std::span<const Point> points, double points_per_cell) {
  if (points.empty()) throw std::invalid_argument("SpatialGrid: no points");
  if (!(points_per_cell > 0.0)) throw std::invalid_argument("SpatialGrid: points_per_cell <= 0");
  double lo_x = points[0].x, hi_x = lo_x, lo_y = points[0].y, hi_y = lo_y;
  for (const Point& p : points) {
    lo_x = std::min(lo_x, p.x);
    hi_x = std::max(hi_x, p.x);
    lo_y = std::min(lo_y, p.y);
    hi_y = std::max(hi_y, p.y);
  }
  const double width = std::max(hi_x - lo_x, 1e-9);
  const double height = std::max(hi_y - lo_y, 1e-9);
  const double cells = std::max(1.0, static_cast<double>(points.size()) / points_per_cell);
  cell_size_ = std::max(std::sqrt(width * height / cells), std::max(width, height) / cells);
  columns_ = static_cast<int>(std::floor(width / cell_size_)) + 1;
  rows_ = static_cast<int>(std::floor(height / cell_size_)) + 1;

  const std::size_t n = points.size();
  column_.resize(n);
  row_.resize(n);
  start_.assign(static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_) + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    column_[i] = std::clamp(static_cast<int>((points[i].x - lo_x) / cell_size_), 0, columns_ - 1);
    row_[i] = std::clamp(static_cast<int>((points[i].y - lo_y) / cell_size_), 0, rows_ - 1);
    ++start_[cell_index(column_[i], row_[i]) + 1];
  }
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  nodes_.resize(n);
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < n; ++i)
    nodes_[fill[cell_index(column_[i], row_[i])]++] = static_cast<std::uint32_t>(i);
}

}  // namespace antslam::tsp
