#include "antslam/frontend/distance_field.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace antslam::frontend {

void CellBox::extend(std::int64_t x, std::int64_t y) {
  if (empty()) {
    *this = {x, y, x, y};
    return;
  }
  x0 = std::min(x0, x);
  y0 = std::min(y0, y);
  x1 = std::max(x1, x);
  y1 = std::max(y1, y);
}

void CellBox::extend(const CellBox& other) {
  if (other.empty()) return;
  extend(other.x0, other.y0);
  extend(other.x1, other.y1);
}

DistanceField::DistanceField(double resolution, double max_distance)
    : resolution_(resolution), max_distance_(max_distance) {
  if (!(resolution > 0.0) || !(max_distance > 0.0) || !std::isfinite(resolution) ||
      !std::isfinite(max_distance))
    throw std::invalid_argument("distance field: resolution and max distance must be positive");
}

void DistanceField::cover(const CellBox& box) {
  if (box.empty() || bounds_.contains(box)) return;
  CellBox wanted = bounds_;
  wanted.extend(box);
  // Grow by a margin (a quarter of the size, at least 64 cells) so that growth is amortised.
  const std::int64_t margin =
      std::max<std::int64_t>(64, std::max(wanted.x1 - wanted.x0, wanted.y1 - wanted.y0) / 4);
  CellBox grown = bounds_.empty() ? box.grown(margin) : bounds_;
  if (box.x0 < grown.x0) grown.x0 = box.x0 - margin;
  if (box.y0 < grown.y0) grown.y0 = box.y0 - margin;
  if (box.x1 > grown.x1) grown.x1 = box.x1 + margin;
  if (box.y1 > grown.y1) grown.y1 = box.y1 + margin;
  const double count = (static_cast<double>(grown.x1) - static_cast<double>(grown.x0) + 1.0) *
                       (static_cast<double>(grown.y1) - static_cast<double>(grown.y0) + 1.0);
  if (!(count <= kMaxGridCells)) {
    std::ostringstream message;
    message << "the scans would need a grid of " << count << " cells of " << resolution_
            << " m (more than " << kMaxGridCells
            << "): a pose or a laser reading of the log is implausibly far away";
    throw std::runtime_error(message.str());
  }
  const std::int64_t width = grown.x1 - grown.x0 + 1;
  std::vector<float> cells(static_cast<std::size_t>(width * (grown.y1 - grown.y0 + 1)),
                           static_cast<float>(max_distance_));
  for (std::int64_t y = bounds_.y0; !bounds_.empty() && y <= bounds_.y1; ++y) {
    const float* src = cells_.data() + (y - bounds_.y0) * stride();
    std::copy(src, src + stride(),
              cells.begin() + (y - grown.y0) * width + (bounds_.x0 - grown.x0));
  }
  cells_ = std::move(cells);
  bounds_ = grown;
}

void DistanceField::insert(std::span<const Eigen::Vector2d> points) {
  if (points.empty()) return;
  const auto radius = static_cast<std::int64_t>(std::ceil(max_distance_ / resolution_));
  CellBox box;
  for (const Eigen::Vector2d& p : points) box.extend(cell_x(p.x()), cell_y(p.y()));
  cover(box.grown(radius));
  const double max_squared = max_distance_ * max_distance_;
  const std::int64_t w = stride();
  for (const Eigen::Vector2d& p : points) {
    const std::int64_t cx = cell_x(p.x()), cy = cell_y(p.y());
    for (std::int64_t y = cy - radius; y <= cy + radius; ++y) {
      const double dy = static_cast<double>(y) * resolution_ - p.y();
      float* row = cells_.data() + (y - bounds_.y0) * w - bounds_.x0;
      for (std::int64_t x = cx - radius; x <= cx + radius; ++x) {
        const double dx = static_cast<double>(x) * resolution_ - p.x();
        const double squared = dx * dx + dy * dy;
        float& cell = row[x];
        if (squared < max_squared && squared < static_cast<double>(cell) * cell)
          cell = static_cast<float>(std::sqrt(squared));
      }
    }
  }
}

float DistanceField::at(std::int64_t x, std::int64_t y) const {
  if (x < bounds_.x0 || x > bounds_.x1 || y < bounds_.y0 || y > bounds_.y1)
    return static_cast<float>(max_distance_);
  return cells_[static_cast<std::size_t>((y - bounds_.y0) * stride() + (x - bounds_.x0))];
}

double DistanceField::interpolate(const Eigen::Vector2d& p, Eigen::Vector2d* gradient) const {
  const double fx = p.x() / resolution_, fy = p.y() / resolution_;
  const std::int64_t x = floor_index(fx), y = floor_index(fy);
  const double tx = fx - static_cast<double>(x), ty = fy - static_cast<double>(y);
  double d00, d10, d01, d11;
  if (x >= bounds_.x0 && x < bounds_.x1 && y >= bounds_.y0 && y < bounds_.y1) {
    const float* c = cells_.data() + (y - bounds_.y0) * stride() + (x - bounds_.x0);
    d00 = c[0];
    d10 = c[1];
    d01 = c[stride()];
    d11 = c[stride() + 1];
  } else {
    d00 = at(x, y);
    d10 = at(x + 1, y);
    d01 = at(x, y + 1);
    d11 = at(x + 1, y + 1);
  }
  const double bottom = d00 + tx * (d10 - d00), top = d01 + tx * (d11 - d01);
  if (gradient != nullptr) {
    *gradient =
        Eigen::Vector2d((1.0 - ty) * (d10 - d00) + ty * (d11 - d01), top - bottom) / resolution_;
  }
  return bottom + ty * (top - bottom);
}

}  // namespace antslam::frontend
