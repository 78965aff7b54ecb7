#pragma once
// A uniform bucket grid over the node coordinates, about two nodes per cell. Cells are stored
// CSR-style (the nodes of cell c are points_in(c)). Used for k-nearest-neighbour lists and for
// the construction's nearest-unvisited fallback, both in about O(1) per query on uniform data
// (Bentley 1990, "K-d trees for semidynamic point sets", uses the same cell idea).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "antslam/tsp/distance.hpp"

namespace antslam::tsp {

class SpatialGrid {
 public:
  /// points_per_cell: mean occupancy the cell size is chosen for (> 0).
  explicit SpatialGrid(std::span<const Point> points, double points_per_cell = 2.0);

  int columns() const { return columns_; }
  int rows() const { return rows_; }
  double cell_size() const { return cell_size_; }
  std::size_t cell_count() const { return start_.size() - 1; }

  std::size_t cell_index(int column, int row) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_) +
           static_cast<std::size_t>(column);
  }
  int column_of(std::uint32_t node) const { return column_[node]; }
  int row_of(std::uint32_t node) const { return row_[node]; }
  /// Index of cell c's first node in the CSR arrays; its nodes are [start(c), start(c + 1)).
  std::uint32_t start(std::size_t cell) const { return start_[cell]; }
  /// Nodes ordered by cell.
  std::span<const std::uint32_t> nodes() const { return nodes_; }
  std::span<const std::uint32_t> points_in(std::size_t cell) const {
    return {nodes_.data() + start_[cell], start_[cell + 1] - start_[cell]};
  }

  /// Calls f(cell) for every cell at Chebyshev distance exactly r from (column, row), clipped
  /// to the grid. Every node outside rings 0..r lies at least r * cell_size() away (in plain
  /// coordinates) from any point of the centre cell.
  template <class F>
  void for_each_cell_in_ring(int column, int row, int r, F&& f) const {
    const int x0 = std::max(column - r, 0), x1 = std::min(column + r, columns_ - 1);
    if (r == 0) {
      f(cell_index(column, row));
      return;
    }
    if (row - r >= 0)
      for (int x = x0; x <= x1; ++x) f(cell_index(x, row - r));
    if (row + r < rows_)
      for (int x = x0; x <= x1; ++x) f(cell_index(x, row + r));
    for (int y = std::max(row - r + 1, 0); y <= std::min(row + r - 1, rows_ - 1); ++y) {
      if (column - r >= 0) f(cell_index(column - r, y));
      if (column + r < columns_) f(cell_index(column + r, y));
    }
  }
  /// True when rings 0..r around (column, row) cover the whole grid.
  bool ring_covers_grid(int column, int row, int r) const {
    return column - r <= 0 && row - r <= 0 && column + r >= columns_ - 1 && row + r >= rows_ - 1;
  }

 private:
  int columns_ = 1;
  int rows_ = 1;
  double cell_size_ = 1.0;
  std::vector<int> column_;
  std::vector<int> row_;
  std::vector<std::uint32_t> start_;
  std::vector<std::uint32_t> nodes_;
};

}  // namespace antslam::tsp
