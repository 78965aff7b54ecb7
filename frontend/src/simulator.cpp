#include "antslam/frontend/simulator.hpp"

#include <cmath>
#include <stdexcept>

#include "antslam/frontend/odometry_noise.hpp"
#include "antslam/slamgraph/gaussian2.hpp"

namespace antslam::frontend {

namespace {

using V = Eigen::Vector2d;

/// Distance along the ray o + t u to the segment, or +inf if it misses.
double ray_hit(const V& o, const V& u, const Segment& s) {
  const V e = s.b - s.a;
  const double denom = u.x() * e.y() - u.y() * e.x();
  if (std::abs(denom) < 1e-12) return INFINITY;
  const V w = s.a - o;
  const double t = (w.x() * e.y() - w.y() * e.x()) / denom;
  const double along = (w.x() * u.y() - w.y() * u.x()) / denom;
  return t > 0.0 && along >= 0.0 && along <= 1.0 ? t : INFINITY;
}

}  // namespace

void World::add_polyline(std::initializer_list<Eigen::Vector2d> corners, bool closed) {
  const std::vector<V> c(corners);
  for (std::size_t i = 0; i + 1 < c.size(); ++i) walls.push_back({c[i], c[i + 1]});
  if (closed && c.size() > 2) walls.push_back({c.back(), c.front()});
}

void World::add_box(const Eigen::Vector2d& center, double width, double height) {
  const V h(width / 2.0, height / 2.0);
  add_polyline({center - h, center + V(h.x(), -h.y()), center + h, center + V(-h.x(), h.y())},
               true);
}

World room_world() {
  World w;
  // Outer walls with an alcove on the upper wall.
  w.add_polyline(
      {V(-4, -3), V(4, -3), V(4, 3), V(1.5, 3), V(1.5, 3.8), V(-0.5, 3.8), V(-0.5, 3), V(-4, 3)},
      true);
  w.add_box(V(1.5, 1.0), 0.6, 0.4);
  w.add_box(V(-2.0, -1.5), 0.8, 0.8);
  w.add_box(V(2.6, -2.0), 0.3, 0.3);
  w.add_box(V(-3.0, 1.8), 0.5, 1.2);
  return w;
}

World corridor_world(double length, double width) {
  World w;
  w.add_polyline({V(-length / 2.0, -width / 2.0), V(length / 2.0, -width / 2.0)});
  w.add_polyline({V(-length / 2.0, width / 2.0), V(length / 2.0, width / 2.0)});
  return w;
}

World loop_world() {
  World w;
  // Outer wall, counter-clockwise, with door recesses of different widths and depths. The four
  // corridors differ in width (bottom 2.4 m, right 3.0 m, top 2.0 m, left 2.8 m), as in real
  // buildings, so that one does not pass for another.
  w.add_polyline(
      {V(-1.4, -1.2), V(3, -1.2),    V(3, -1.8),    V(4, -1.8),    V(4, -1.2),   V(9, -1.2),
       V(9, -2.0),    V(10.5, -2.0), V(10.5, -1.2), V(15, -1.2),   V(15, -1.6),  V(15.8, -1.6),
       V(15.8, -1.2), V(21.5, -1.2), V(21.5, 5),    V(22.3, 5),    V(22.3, 6.2), V(21.5, 6.2),
       V(21.5, 15.0), V(17, 15.0),   V(17, 15.7),   V(16, 15.7),   V(16, 15.0),  V(9, 15.0),
       V(9, 15.4),    V(7, 15.4),    V(7, 15.0),    V(-1.4, 15.0), V(-1.4, 9),   V(-2.3, 9),
       V(-2.3, 8),    V(-1.4, 8)},
      true);
  // The inner block, with a bay on its right side.
  w.add_polyline({V(1.4, 1.2), V(18.5, 1.2), V(18.5, 7.5), V(17.9, 7.5), V(17.9, 9.0), V(18.5, 9.0),
                  V(18.5, 13.0), V(1.4, 13.0)},
                 true);
  // Pillars and furniture, placed irregularly.
  w.add_box(V(5.5, 1.45), 0.5, 0.5);
  w.add_box(V(12.0, -0.8), 0.4, 0.8);
  w.add_box(V(20.9, 2.5), 0.6, 0.3);
  w.add_box(V(19.0, 11.0), 0.3, 0.3);
  w.add_box(V(13.0, 14.6), 1.2, 0.4);
  w.add_box(V(4.0, 13.3), 0.3, 0.3);
  w.add_box(V(-0.9, 5.0), 0.5, 1.5);
  w.add_box(V(1.1, 10.5), 0.3, 0.6);
  return w;
}

std::vector<Eigen::Vector2d> loop_waypoints() {
  return {V(0, 0), V(20, 0), V(20, 14), V(0, 14), V(0, 0)};
}

LaserScan simulate_scan(const World& world, const slam::Pose2& robot,
                        const SimulationSettings& settings, aco::Rng& rng) {
  if (settings.beams < 2) throw std::invalid_argument("simulator: need at least 2 beams");
  LaserScan scan;
  scan.first_angle = -settings.field_of_view / 2.0;
  scan.angle_step = settings.field_of_view / static_cast<double>(settings.beams - 1);
  scan.max_range = settings.max_range;
  scan.ranges.resize(settings.beams);
  const V origin = robot.translation();
  for (std::size_t k = 0; k < settings.beams; ++k) {
    const double angle = robot.theta + scan.beam_angle(k);
    const V u(std::cos(angle), std::sin(angle));
    double r = INFINITY;
    for (const Segment& s : world.walls) r = std::min(r, ray_hit(origin, u, s));
    const double noise = settings.range_noise * slam::standard_normal(rng);
    scan.ranges[k] =
        static_cast<float>(r < settings.max_range ? std::max(0.0, r + noise) : settings.max_range);
  }
  return scan;
}

namespace {

/// The true poses: turn toward each next waypoint, then drive to it.
std::vector<slam::Pose2> true_path(std::span<const Eigen::Vector2d> waypoints,
                                   const SimulationSettings& s) {
  if (waypoints.size() < 2) throw std::invalid_argument("simulator: need at least 2 waypoints");
  std::vector<slam::Pose2> path;
  const V d0 = waypoints[1] - waypoints[0];
  slam::Pose2 pose{waypoints[0].x(), waypoints[0].y(), std::atan2(d0.y(), d0.x())};
  path.push_back(pose);
  for (std::size_t w = 1; w < waypoints.size(); ++w) {
    const V d = waypoints[w] - pose.translation();
    const double turn = slam::wrap_angle(std::atan2(d.y(), d.x()) - pose.theta);
    const auto turns = static_cast<int>(std::ceil(std::abs(turn) / s.turn_step));
    const double heading = pose.theta;
    for (int k = 1; k <= turns; ++k) {
      pose.theta = slam::wrap_angle(heading + turn * k / turns);
      path.push_back(pose);
    }
    const V start = pose.translation();
    const auto steps = static_cast<int>(std::ceil(d.norm() / s.step));
    for (int k = 1; k <= steps; ++k) {
      const V p = start + d * (static_cast<double>(k) / steps);
      pose.x = p.x();
      pose.y = p.y();
      path.push_back(pose);
    }
  }
  return path;
}

}  // namespace

SimulatedRun simulate_run(const World& world, std::span<const Eigen::Vector2d> waypoints,
                          const SimulationSettings& settings, std::uint64_t seed) {
  const std::vector<slam::Pose2> path = true_path(waypoints, settings);
  aco::Rng scan_rng(aco::mix_seed(seed, 1));
  aco::Rng odometry_rng(aco::mix_seed(seed, 2));
  SimulatedRun run;
  run.log.source = "simulation";
  run.log.flaser_geometry.field_of_view = settings.field_of_view;
  run.log.flaser_geometry.max_range = settings.max_range;
  const OdometryNoise noise{settings.odometry_noise_linear, settings.odometry_noise_angular,
                            settings.odometry_noise_drift, settings.heading_bias};
  const std::vector<slam::Pose2> odometry = noisy_odometry(path, noise, odometry_rng);
  for (std::size_t i = 0; i < path.size(); ++i) {
    LaserScan scan = simulate_scan(world, path[i], settings, scan_rng);
    scan.stamp = static_cast<double>(i) * settings.scan_period;
    scan.odometry = odometry[i];
    run.log.scans.push_back(std::move(scan));
    run.truth.push_back({static_cast<double>(i) * settings.scan_period, path[i]});
  }
  return run;
}

}  // namespace antslam::frontend
