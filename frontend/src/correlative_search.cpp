#include "antslam/frontend/correlative_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace antslam::frontend {

namespace {

/// The `size` best candidates, at most one per peak: a candidate within two lattice steps (in
/// translation and in heading) of a kept one replaces it if better, else is dropped.
class BestPeaks {
 public:
  BestPeaks(std::size_t size, double linear, double angular)
      : size_(size), linear_(linear), angular_(angular) {}

  double threshold() const {
    return kept_.size() < size_ ? std::numeric_limits<double>::infinity() : kept_.back().score;
  }

  void offer(const SearchResult& c) {
    if (c.score >= threshold()) return;
    // Kept candidates never lie near each other: c enters only if it beats every kept one
    // near it, and replaces them all.
    const auto near = [&](const SearchResult& k) {
      return std::abs(k.pose.x - c.pose.x) <= linear_ && std::abs(k.pose.y - c.pose.y) <= linear_ &&
             std::abs(slam::wrap_angle(k.pose.theta - c.pose.theta)) <= angular_;
    };
    for (const SearchResult& k : kept_)
      if (near(k) && k.score <= c.score) return;
    std::erase_if(kept_, near);
    if (kept_.size() == size_) kept_.pop_back();
    kept_.insert(std::upper_bound(kept_.begin(), kept_.end(), c,
                                  [](const SearchResult& a, const SearchResult& b) {
                                    return a.score < b.score;
                                  }),
                 c);
  }

  std::vector<SearchResult> take() { return std::move(kept_); }

 private:
  std::size_t size_;
  double linear_, angular_;
  std::vector<SearchResult> kept_;
};

}  // namespace

std::vector<SearchResult> correlative_peaks(DistanceField& field,
                                            std::span<const Eigen::Vector2d> points,
                                            const slam::Pose2& center, const SearchWindow& window,
                                            const PosePrior& prior, std::size_t peaks) {
  if (!(window.linear >= 0.0) || !(window.angular >= 0.0) || !(window.angular_step > 0.0))
    throw std::invalid_argument("search window: negative size or non-positive angular step");
  const double res = field.resolution();
  const auto reach = static_cast<std::int64_t>(std::ceil(window.linear / res));
  const auto turns = static_cast<std::int64_t>(std::floor(window.angular / window.angular_step));
  double radius = 0.0;
  for (const Eigen::Vector2d& p : points) radius = std::max(radius, p.norm());
  const std::int64_t cx = field.cell_x(center.x), cy = field.cell_y(center.y);
  const auto span_cells = static_cast<std::int64_t>(std::ceil(radius / res)) + reach + 2;
  field.cover(CellBox{cx - span_cells, cy - span_cells, cx + span_cells, cy + span_cells});

  const std::int64_t stride = field.stride();
  const CellBox& b = field.bounds();
  const float* cells = field.data();
  const std::int64_t side = 2 * reach + 1;
  std::vector<double> sums(static_cast<std::size_t>(side * side));
  // Two lattice steps (and a half, so that rounding never splits a peak) make one peak.
  BestPeaks best(std::max<std::size_t>(1, peaks), 2.5 * res, 2.5 * window.angular_step);
  const double linear_weight = prior.weight / (prior.linear_std * prior.linear_std);
  const double angular_weight = prior.weight / (prior.angular_std * prior.angular_std);
  for (std::int64_t k = -turns; k <= turns; ++k) {
    const double theta = center.theta + static_cast<double>(k) * window.angular_step;
    const slam::Pose2 rotated{center.x, center.y, theta};
    const double turn = slam::wrap_angle(theta - prior.mean.theta);
    const double turn_penalty = angular_weight * turn * turn;
    std::fill(sums.begin(), sums.end(), 0.0);
    for (const Eigen::Vector2d& p : points) {
      const Eigen::Vector2d q = rotated * p;
      const std::int64_t x = field.cell_x(q.x()) - reach - b.x0;
      const std::int64_t y = field.cell_y(q.y()) - reach - b.y0;
      for (std::int64_t dy = 0; dy < side; ++dy) {
        const float* row = cells + (y + dy) * stride + x;
        double* out = sums.data() + dy * side;
        for (std::int64_t dx = 0; dx < side; ++dx) {
          const double d = row[dx];
          out[dx] += d * d;
        }
      }
    }
    for (std::int64_t dy = 0; dy < side; ++dy)
      for (std::int64_t dx = 0; dx < side; ++dx) {
        // The translation moves the pose by whole cells; the points' cells moved with it.
        const double x = center.x + static_cast<double>(dx - reach) * res;
        const double y = center.y + static_cast<double>(dy - reach) * res;
        const double sum = sums[static_cast<std::size_t>(dy * side + dx)];
        const double ex = x - prior.mean.x, ey = y - prior.mean.y;
        const double score = sum + turn_penalty + linear_weight * (ex * ex + ey * ey);
        if (score < best.threshold())
          best.offer({slam::Pose2{x, y, slam::wrap_angle(theta)}, sum, score});
      }
  }
  return best.take();
}

SearchResult correlative_search(DistanceField& field, std::span<const Eigen::Vector2d> points,
                                const slam::Pose2& center, const SearchWindow& window,
                                const PosePrior& prior) {
  std::vector<SearchResult> peaks = correlative_peaks(field, points, center, window, prior, 1);
  return peaks.empty() ? SearchResult{center, 0.0, std::numeric_limits<double>::infinity()}
                       : peaks.front();
}

}  // namespace antslam::frontend
