#include "antslam/frontend/scan_points.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_set>

#include "antslam/frontend/distance_field.hpp"

namespace antslam::frontend {

ScanSurfaces scan_surfaces(const LaserScan& scan, double min_range, double max_range,
                           double lambda) {
  const double limit = std::min(max_range, scan.max_range);
  const double step = std::abs(scan.angle_step);
  const double gap_per_metre = lambda > step ? std::sin(step) / std::sin(lambda - step) : 0.0;
  ScanSurfaces out;
  out.points.reserve(scan.ranges.size());
  out.joins_next.reserve(scan.ranges.size());
  double previous_range = -1.0;  // < 0: the previous beam gave no point
  for (std::size_t k = 0; k < scan.ranges.size(); ++k) {
    const double r = scan.ranges[k];
    if (!(r >= min_range && r < limit)) {
      previous_range = -1.0;
      continue;
    }
    const double a = scan.beam_angle(k);
    const Eigen::Vector2d p = scan.laser_pose * Eigen::Vector2d(r * std::cos(a), r * std::sin(a));
    if (previous_range >= 0.0) {
      const double gap = (p - out.points.back()).norm();
      out.joins_next.back() = gap <= gap_per_metre * std::min(r, previous_range) ? 1 : 0;
    }
    out.points.push_back(p);
    out.joins_next.push_back(0);
    previous_range = r;
  }
  return out;
}

Points supported_points(const ScanSurfaces& s) {
  Points out;
  out.reserve(s.points.size());
  for (std::size_t k = 0; k < s.points.size(); ++k) {
    const bool before = k > 0 && s.joins_next[k - 1] != 0;
    if (before || s.joins_next[k] != 0) out.push_back(s.points[k]);
  }
  return out;
}

Points dense_points(const ScanSurfaces& s, double spacing) {
  Points out;
  out.reserve(s.points.size() * 2);
  for (std::size_t k = 0; k < s.points.size(); ++k) {
    out.push_back(s.points[k]);
    if (s.joins_next[k] == 0) continue;
    const Eigen::Vector2d d = s.points[k + 1] - s.points[k];
    const auto steps = static_cast<int>(std::ceil(d.norm() / spacing));
    for (int i = 1; i < steps; ++i)
      out.push_back(s.points[k] + d * (static_cast<double>(i) / steps));
  }
  return out;
}

Points thin_points(std::span<const Eigen::Vector2d> points, double spacing) {
  Points kept;
  std::unordered_set<std::uint64_t> cells;
  cells.reserve(points.size());
  // The low 32 bits of the cell indices: exact while the points span fewer than 2^32 cells
  // (2e8 m at 5 cm), as the points of a scan or a fragment do.
  for (const Eigen::Vector2d& p : points) {
    const auto x = static_cast<std::uint32_t>(floor_index(p.x() / spacing));
    const auto y = static_cast<std::uint32_t>(floor_index(p.y() / spacing));
    if (cells.insert((std::uint64_t{x} << 32U) | y).second) kept.push_back(p);
  }
  return kept;
}

Points transform_points(const slam::Pose2& pose, std::span<const Eigen::Vector2d> points) {
  Points out;
  out.reserve(points.size());
  for (const Eigen::Vector2d& p : points) out.push_back(pose * p);
  return out;
}

}  // namespace antslam::frontend
