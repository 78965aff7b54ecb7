#include "antslam/baselines/tinyslam.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "antslam/slamgraph/gaussian2.hpp"

namespace antslam::baselines {

void validate(const TinySlamSettings& s) {
  const auto positive = [](double value, const char* field) {
    if (!(value > 0.0 && std::isfinite(value)))
      throw std::invalid_argument(std::string("tinyslam: ") + field + " must be > 0");
  };
  const auto unit = [](double value, const char* field) {
    if (!(value > 0.0 && value <= 1.0))
      throw std::invalid_argument(std::string("tinyslam: ") + field + " must be in (0, 1]");
  };
  positive(s.resolution, "resolution");
  positive(s.max_range, "max_range");
  positive(s.sigma_xy, "sigma_xy");
  positive(s.sigma_theta, "sigma_theta");
  unit(s.quality, "quality");
  unit(s.refined_quality, "refined_quality");
  if (!(s.min_range >= 0.0 && s.min_range < s.max_range))
    throw std::invalid_argument("tinyslam: min_range must be in [0, max_range)");
  if (!(s.hole_width >= 0.0 && std::isfinite(s.hole_width)))
    throw std::invalid_argument("tinyslam: hole_width must be >= 0");
  if (s.stop == 0 || s.stop > kMaxStop)
    throw std::invalid_argument("tinyslam: stop must be in [1, " + std::to_string(kMaxStop) + "]");
}

std::vector<Eigen::Vector2d> scan_points(const frontend::LaserScan& scan,
                                         const TinySlamSettings& settings) {
  std::vector<Eigen::Vector2d> points;
  points.reserve(scan.ranges.size());
  const double max_range = std::min(settings.max_range, scan.max_range);
  for (std::size_t k = 0; k < scan.ranges.size(); ++k) {
    const double r = scan.ranges[k];
    if (r < settings.min_range || r >= max_range) continue;
    const double a = scan.beam_angle(k);
    points.push_back(scan.laser_pose * Eigen::Vector2d(r * std::cos(a), r * std::sin(a)));
  }
  return points;
}

double correspondence(const OccupancyGrid& map, std::span<const Eigen::Vector2d> points,
                      const slam::Pose2& pose) {
  if (points.empty()) return 0.0;
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  double sum = 0.0;
  for (const Eigen::Vector2d& p : points)
    sum += map.at(Eigen::Vector2d(pose.x + c * p.x() - s * p.y(), pose.y + s * p.x() + c * p.y()));
  return sum / static_cast<double>(points.size());
}

SearchResult monte_carlo_search(const OccupancyGrid& map, std::span<const Eigen::Vector2d> points,
                                const slam::Pose2& start, const TinySlamSettings& settings,
                                aco::Rng& rng) {
  SearchResult best{start, correspondence(map, points, start), 1};
  slam::Pose2 centre = start;
  double centre_score = best.score;
  double sigma_xy = settings.sigma_xy, sigma_theta = settings.sigma_theta;
  std::size_t failures = 0;
  while (failures < settings.stop) {
    const slam::Pose2 draw{
        centre.x + sigma_xy * slam::standard_normal(rng),
        centre.y + sigma_xy * slam::standard_normal(rng),
        slam::wrap_angle(centre.theta + sigma_theta * slam::standard_normal(rng))};
    const double score = correspondence(map, points, draw);
    ++best.evaluations;
    if (score > best.score) {
      best.pose = draw;
      best.score = score;
    } else {
      ++failures;
    }
    if (failures > settings.stop / 3 && best.score > centre_score) {
      centre = best.pose;
      centre_score = best.score;
      failures = 0;
      sigma_xy *= 0.5;
      sigma_theta *= 0.5;
    }
  }
  return best;
}

namespace {

const TinySlamSettings& validated(const TinySlamSettings& settings) {
  validate(settings);
  return settings;
}

}  // namespace

TinySlam::TinySlam(const TinySlamSettings& settings)
    : settings_(validated(settings)),
      map_(settings.resolution, settings.max_cells),
      rng_(aco::mix_seed(settings.seed, 0x71E5)) {}

void TinySlam::insert(std::span<const Eigen::Vector2d> points, const slam::Pose2& pose,
                      double quality) {
  const Eigen::Vector2d origin = pose.translation();
  for (const Eigen::Vector2d& p : points)
    map_.insert_beam(origin, pose * p, quality, settings_.hole_width);
}

slam::Pose2 TinySlam::add_scan(const frontend::LaserScan& scan) {
  const std::vector<Eigen::Vector2d> points = scan_points(scan, settings_);
  if (!started_) {
    started_ = true;
    pose_ = scan.odometry;
    odometry_ = scan.odometry;
    insert(points, pose_, settings_.quality);
    return pose_;
  }
  // Tracking: the previous pose moved by the odometry increment.
  const slam::Pose2 prediction = pose_ * slam::between(odometry_, scan.odometry);
  odometry_ = scan.odometry;
  if (points.size() < settings_.min_points) {
    ++unmatched_;
    pose_ = prediction;
    return pose_;
  }
  const SearchResult found = monte_carlo_search(map_, points, prediction, settings_, rng_);
  evaluations_ += found.evaluations;
  const bool moved = found.pose.x != prediction.x || found.pose.y != prediction.y ||
                     found.pose.theta != prediction.theta;
  pose_ = found.pose;
  insert(points, pose_, moved ? settings_.refined_quality : settings_.quality);
  return pose_;
}

TinySlamResult run_tinyslam(const frontend::LaserLog& log, const TinySlamSettings& settings,
                            const std::function<void(std::size_t)>& progress) {
  TinySlam slam(settings);
  slam::Trajectory trajectory;
  trajectory.reserve(log.scans.size());
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    trajectory.push_back({log.scans[i].stamp, slam.add_scan(log.scans[i])});
    if (progress) progress(i + 1);
  }
  return {std::move(trajectory), slam.map(), slam.evaluations(), slam.unmatched()};
}

frontend::Image map_image(const OccupancyGrid& map) {
  // Crop to the cells ever written (the grid grows with a margin), plus a border of 10 cells.
  std::int64_t x0 = map.min_x() + map.width(), y0 = map.min_y() + map.height(), x1 = x0 - 1,
               y1 = y0 - 1;
  for (std::int64_t y = map.min_y(); y < map.min_y() + map.height(); ++y)
    for (std::int64_t x = map.min_x(); x < map.min_x() + map.width(); ++x)
      if (map.at(x, y) != 0.5F) {
        x0 = std::min(x0, x);
        x1 = std::max(x1, x);
        y0 = std::min(y0, y);
        y1 = std::max(y1, y);
      }
  if (x1 < x0) return frontend::Image(1, 1, {128, 128, 128});
  constexpr std::int64_t border = 10;
  const auto w = static_cast<std::size_t>(x1 - x0 + 1 + 2 * border);
  const auto h = static_cast<std::size_t>(y1 - y0 + 1 + 2 * border);
  frontend::Image image(w, h);
  for (std::size_t row = 0; row < h; ++row)
    for (std::size_t col = 0; col < w; ++col) {
      const float m = map.at(x0 - border + static_cast<std::int64_t>(col),
                             y1 + border - static_cast<std::int64_t>(row));  // north up
      const auto grey = static_cast<std::uint8_t>(std::lround(255.0 * (1.0 - m)));
      image.at(col, row) = {grey, grey, grey};
    }
  return image;
}

}  // namespace antslam::baselines
