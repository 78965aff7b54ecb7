#pragma once
// Precomputation grids for branch-and-bound scan matching (Hess et al. 2016, "Real-time loop
// closure in 2D LIDAR SLAM", Sec. V-C): level 0 holds the likelihood exp(-d^2 / (2 sigma^2)) of
// every cell of a distance field (0 outside it); level h holds, at cell (x, y), the largest
// level-0 value in the 2^h x 2^h window [x, x + 2^h) x [y, y + 2^h). A point set placed with a
// translation anywhere in such a window thus scores at most the sum of level-h values: the bound
// that lets a search discard whole windows of translations.

#include <cstdint>
#include <vector>

#include "antslam/frontend/distance_field.hpp"

namespace antslam::frontend {

class LikelihoodPyramid {
 public:
  /// `levels` >= 1 grids (level 0 to levels - 1) from the field, with the likelihood std sigma.
  LikelihoodPyramid(const DistanceField& field, double sigma, int levels);

  int levels() const { return static_cast<int>(grids_.size()); }
  double resolution() const { return resolution_; }
  /// Lattice cell of a point (the field's lattice).
  std::int64_t cell(double v) const { return floor_index(v / resolution_ + 0.5); }

  /// The grid of one level: values at (x - x0, y - y0) row-major with `width` columns; the
  /// covered cells are the same for every level.
  const float* level(int h) const { return grids_[static_cast<std::size_t>(h)].data(); }
  std::int64_t x0() const { return x0_; }
  std::int64_t y0() const { return y0_; }
  std::int64_t width() const { return width_; }
  std::int64_t height() const { return height_; }

  /// Level-h value of the window starting at lattice cell (x, y); 0 where no map is.
  float at(int level, std::int64_t x, std::int64_t y) const {
    if (x < x0_ || y < y0_ || x >= x0_ + width_ || y >= y0_ + height_) return 0.0F;
    return grids_[static_cast<std::size_t>(level)]
                 [static_cast<std::size_t>((y - y0_) * width_ + (x - x0_))];
  }

 private:
  double resolution_;
  std::int64_t x0_ = 0, y0_ = 0, width_ = 0, height_ = 0;  ///< covered cells (all levels)
  std::vector<std::vector<float>> grids_;
};

}  // namespace antslam::frontend
