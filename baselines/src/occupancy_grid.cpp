#include "antslam/baselines/occupancy_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "antslam/frontend/distance_field.hpp"

namespace antslam::baselines {

OccupancyGrid::OccupancyGrid(double resolution, std::size_t max_cells)
    : resolution_(resolution), max_cells_(max_cells) {
  if (!(resolution > 0.0 && std::isfinite(resolution)))
    throw std::invalid_argument("occupancy grid: resolution must be a positive number of metres");
}

std::int64_t OccupancyGrid::cell(double coordinate) const {
  return frontend::floor_index(coordinate / resolution_);
}

float OccupancyGrid::at(std::int64_t x, std::int64_t y) const {
  if (x < x0_ || y < y0_ || x >= x0_ + width_ || y >= y0_ + height_) return 0.5F;
  return cells_[static_cast<std::size_t>((y - y0_) * width_ + (x - x0_))];
}

void OccupancyGrid::update(std::int64_t x, std::int64_t y, double quality, double value) {
  cover(x, y, x, y);
  float& m = cells_[static_cast<std::size_t>((y - y0_) * width_ + (x - x0_))];
  m = static_cast<float>((1.0 - quality) * m + quality * value);  // Eq. (1)
}

void OccupancyGrid::cover(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1) {
  if (!cells_.empty() && x0 >= x0_ && y0 >= y0_ && x1 < x0_ + width_ && y1 < y0_ + height_) return;
  // Grow with a margin of half the current size, so that a growing map is copied O(log) times.
  std::int64_t nx0 = x0, ny0 = y0, nx1 = x1, ny1 = y1;
  if (!cells_.empty()) {
    const std::int64_t mx = width_ / 2 + 16, my = height_ / 2 + 16;
    nx0 = std::min(x0, x0_ - (x0 < x0_ ? mx : 0));
    ny0 = std::min(y0, y0_ - (y0 < y0_ ? my : 0));
    nx1 = std::max(x1, x0_ + width_ - 1 + (x1 >= x0_ + width_ ? mx : 0));
    ny1 = std::max(y1, y0_ + height_ - 1 + (y1 >= y0_ + height_ ? my : 0));
  }
  const std::int64_t w = nx1 - nx0 + 1, h = ny1 - ny0 + 1;
  if (static_cast<double>(w) * static_cast<double>(h) > static_cast<double>(max_cells_))
    throw std::runtime_error("occupancy grid: the map would grow to " + std::to_string(w) + " x " +
                             std::to_string(h) + " cells, more than the limit of " +
                             std::to_string(max_cells_));
  std::vector<float> cells(static_cast<std::size_t>(w * h), 0.5F);
  for (std::int64_t y = 0; y < height_; ++y)
    std::copy_n(cells_.begin() + y * width_, width_,
                cells.begin() + ((y + y0_ - ny0) * w + (x0_ - nx0)));
  cells_ = std::move(cells);
  x0_ = nx0;
  y0_ = ny0;
  width_ = w;
  height_ = h;
}

void OccupancyGrid::insert_beam(const Eigen::Vector2d& origin, const Eigen::Vector2d& hit,
                                double quality, double hole_width) {
  const Eigen::Vector2d delta = hit - origin;
  const double range = delta.norm();
  if (!(range > 0.0)) return;
  const Eigen::Vector2d u = delta / range;
  const double half_hole = 0.5 * hole_width;
  const double length = range + half_hole;
  const Eigen::Vector2d end = origin + length * u;
  cover(std::min(cell(origin.x()), cell(end.x())), std::min(cell(origin.y()), cell(end.y())),
        std::max(cell(origin.x()), cell(end.x())), std::max(cell(origin.y()), cell(end.y())));
  const std::int64_t hit_x = cell(hit.x()), hit_y = cell(hit.y());
  // Amanatides and Woo (1987): every cell the segment origin -> end crosses, once, in order.
  const double h = resolution_;
  std::int64_t x = cell(origin.x()), y = cell(origin.y());
  const std::int64_t last_x = cell(end.x()), last_y = cell(end.y());
  const std::int64_t step_x = u.x() > 0.0 ? 1 : -1, step_y = u.y() > 0.0 ? 1 : -1;
  const auto crossing = [h](double p, double d, std::int64_t c, std::int64_t step) -> double {
    if (d == 0.0) return INFINITY;
    return (static_cast<double>(step > 0 ? c + 1 : c) * h - p) / d;
  };
  double next_x = crossing(origin.x(), u.x(), x, step_x);
  double next_y = crossing(origin.y(), u.y(), y, step_y);
  const double delta_x = u.x() != 0.0 ? h / std::abs(u.x()) : INFINITY;
  const double delta_y = u.y() != 0.0 ? h / std::abs(u.y()) : INFINITY;
  for (;;) {
    if (x < x0_ || y < y0_ || x >= x0_ + width_ || y >= y0_ + height_) break;  // rounding guard
    double value = x == hit_x && y == hit_y ? 1.0 : 0.0;
    if (half_hole > 0.0) {
      const Eigen::Vector2d centre((static_cast<double>(x) + 0.5) * h,
                                   (static_cast<double>(y) + 0.5) * h);
      value = std::max(0.0, 1.0 - std::abs((centre - origin).dot(u) - range) / half_hole);
    }
    float& m = cells_[static_cast<std::size_t>((y - y0_) * width_ + (x - x0_))];
    m = static_cast<float>((1.0 - quality) * m + quality * value);  // Eq. (1)
    if (x == last_x && y == last_y) break;
    const double entry = std::min(next_x, next_y);
    if (entry > length) break;  // rounding put the end cell just beside the traversal
    if (next_x < next_y) {
      x += step_x;
      next_x += delta_x;
    } else {
      y += step_y;
      next_y += delta_y;
    }
  }
}

}  // namespace antslam::baselines
