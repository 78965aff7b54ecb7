#pragma once
// A growable grid holding, per cell, the distance from the cell centre to the nearest inserted
// hit point, clamped at `max_distance` (a truncated distance transform). The likelihood field of
// the scan matcher is a Gaussian of this distance (GMapping's and Thrun's "likelihood field"):
//   log p(z_j | m, x) = -d(x (+) z_j)^2 / (2 sigma^2),
// and the clamp makes readings that hit nothing known (max-range, dynamic objects, new space)
// cost the same bounded penalty wherever the scan is put.
//
// Cells sit on a fixed lattice: cell (i, j) has its centre at (i * resolution, j * resolution)
// in the grid's frame, so grids that grow keep their values and cell indices.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace antslam::frontend {

/// floor(v) as a lattice index, v clamped to +-2^52 first: casting a larger (or non-finite)
/// double to an integer is undefined, and a grid that large is refused anyway (kMaxGridCells).
inline std::int64_t floor_index(double v) {
  constexpr double kLimit = 4503599627370496.0;  // 2^52
  return static_cast<std::int64_t>(
      std::floor(std::isnan(v) ? 0.0 : std::clamp(v, -kLimit, kLimit)));
}

/// The most cells a grid of the frontend may have (1 GB of floats): a log whose poses or ranges
/// would need a larger one is implausible (a laser 1e308 m ahead of the robot), and is refused
/// with one line instead of exhausting memory.
inline constexpr double kMaxGridCells = 268435456.0;  // 2^28

/// An axis-aligned box of lattice cells, inclusive bounds.
struct CellBox {
  std::int64_t x0 = 0, y0 = 0, x1 = -1, y1 = -1;  ///< cells; empty when x1 < x0

  bool empty() const { return x1 < x0 || y1 < y0; }
  void extend(std::int64_t x, std::int64_t y);
  void extend(const CellBox& other);
  CellBox grown(std::int64_t margin) const {
    return {x0 - margin, y0 - margin, x1 + margin, y1 + margin};
  }
  bool contains(const CellBox& other) const {
    return other.x0 >= x0 && other.y0 >= y0 && other.x1 <= x1 && other.y1 <= y1;
  }
};

class DistanceField {
 public:
  /// resolution and max_distance in metres, both > 0.
  DistanceField(double resolution, double max_distance);

  double resolution() const { return resolution_; }
  double max_distance() const { return max_distance_; }

  /// The lattice cell nearest to a point.
  std::int64_t cell_x(double x) const { return nearest(x / resolution_); }
  std::int64_t cell_y(double y) const { return nearest(y / resolution_); }

  /// Lowers the distance of every cell within max_distance of each point (points in the grid's
  /// frame, metres). Grows the grid as needed.
  void insert(std::span<const Eigen::Vector2d> points);

  /// Grows the grid (new cells at max_distance) so that it holds every cell of `box`. Throws
  /// std::runtime_error if it would need more than kMaxGridCells cells.
  void cover(const CellBox& box);

  /// The covered cells (empty before the first insert or cover).
  const CellBox& bounds() const { return bounds_; }
  std::int64_t stride() const { return bounds_.x1 - bounds_.x0 + 1; }
  /// Row-major cell distances; index (y - bounds.y0) * stride + (x - bounds.x0).
  const float* data() const { return cells_.data(); }

  /// Distance at a lattice cell; max_distance outside the grid.
  float at(std::int64_t x, std::int64_t y) const;

  /// Bilinear interpolation between cell centres at a point, and its gradient (1/m) if asked.
  double interpolate(const Eigen::Vector2d& p, Eigen::Vector2d* gradient = nullptr) const;

 private:
  static std::int64_t nearest(double v) { return floor_index(v + 0.5); }
  double resolution_;
  double max_distance_;
  CellBox bounds_;
  std::vector<float> cells_;
};

}  // namespace antslam::frontend
