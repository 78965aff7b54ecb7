#include "antslam/frontend/likelihood_pyramid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace antslam::frontend {

LikelihoodPyramid::LikelihoodPyramid(const DistanceField& field, double sigma, int levels)
    : resolution_(field.resolution()) {
  if (levels < 1 || levels > 16) throw std::invalid_argument("pyramid: levels must be in [1, 16]");
  if (!(sigma > 0.0)) throw std::invalid_argument("pyramid: sigma must be positive");
  const CellBox& b = field.bounds();
  if (b.empty()) {
    grids_.assign(static_cast<std::size_t>(levels), {});
    return;
  }
  // Windows that start up to 2^(levels-1) - 1 cells before the field still reach into it.
  const std::int64_t reach = (std::int64_t{1} << (levels - 1)) - 1;
  x0_ = b.x0 - reach;
  y0_ = b.y0 - reach;
  width_ = b.x1 - b.x0 + 1 + reach;
  height_ = b.y1 - b.y0 + 1 + reach;
  const auto size = static_cast<std::size_t>(width_ * height_);
  grids_.assign(static_cast<std::size_t>(levels), std::vector<float>(size, 0.0F));
  const double scale = -1.0 / (2.0 * sigma * sigma);
  std::vector<float>& base = grids_[0];
  for (std::int64_t y = b.y0; y <= b.y1; ++y)
    for (std::int64_t x = b.x0; x <= b.x1; ++x) {
      const double d = field.at(x, y);
      base[static_cast<std::size_t>((y - y0_) * width_ + (x - x0_))] =
          static_cast<float>(std::exp(scale * d * d));
    }
  // Window doubling: [x, x + 2^h) = [x, x + s) u [x + s, x + 2s) with s = 2^(h-1), in x and y.
  for (int h = 1; h < levels; ++h) {
    const std::vector<float>& prev = grids_[static_cast<std::size_t>(h - 1)];
    std::vector<float>& next = grids_[static_cast<std::size_t>(h)];
    const std::int64_t s = std::int64_t{1} << (h - 1);
    for (std::int64_t y = 0; y < height_; ++y)
      for (std::int64_t x = 0; x < width_; ++x) {
        float v = prev[static_cast<std::size_t>(y * width_ + x)];
        if (x + s < width_) v = std::max(v, prev[static_cast<std::size_t>(y * width_ + x + s)]);
        if (y + s < height_) {
          v = std::max(v, prev[static_cast<std::size_t>((y + s) * width_ + x)]);
          if (x + s < width_)
            v = std::max(v, prev[static_cast<std::size_t>((y + s) * width_ + x + s)]);
        }
        next[static_cast<std::size_t>(y * width_ + x)] = v;
      }
  }
}

}  // namespace antslam::frontend
