#pragma once
// A small 2D laser simulator: worlds made of wall segments, ray-cast scans with seeded range
// noise, and robot runs along waypoints with seeded odometry noise. It gives the tests and the
// calibration of the scan matcher's temperature scans with a known true pose.

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

#include "antslam/aco/random.hpp"
#include "antslam/frontend/laser_log.hpp"
#include "antslam/slamgraph/pose2.hpp"
#include "antslam/slamgraph/trajectory.hpp"

namespace antslam::frontend {

struct Segment {
  Eigen::Vector2d a;  ///< metres
  Eigen::Vector2d b;  ///< metres
};

struct World {
  std::vector<Segment> walls;

  /// Walls through consecutive corners; closed adds the wall back to the first corner.
  void add_polyline(std::initializer_list<Eigen::Vector2d> corners, bool closed = false);
  /// An axis-aligned box (a pillar, a cupboard) centred at `center`.
  void add_box(const Eigen::Vector2d& center, double width, double height);
};

/// An 8 m x 6 m room with a few boxes and an alcove: every direction is constrained.
World room_world();
/// Two parallel walls `length` metres long, `width` apart, open at both ends beyond sensor
/// reach: along the corridor a scan says nothing.
World corridor_world(double length = 200.0, double width = 2.0);
/// A rectangular ring corridor (20 m x 14 m on its centre line; the four sides 2.0 m to 3.0 m
/// wide) around a block, with door recesses, pillars and a bay so that places differ.
World loop_world();
/// The centre line of loop_world's corridor, counter-clockwise from (0, 0), as waypoints.
std::vector<Eigen::Vector2d> loop_waypoints();

struct SimulationSettings {
  std::size_t beams = 361;                   ///< readings per scan
  double field_of_view = 3.141592653589793;  ///< radians, first beam at -fov / 2
  double max_range = 30.0;                   ///< metres; no hit -> max_range reading
  double range_noise = 0.01;                 ///< metres, std of Gaussian range noise
  double step = 0.25;                        ///< metres between scans along the path
  double turn_step = 0.2;                    ///< radians, max heading change between scans
  double odometry_noise_linear = 0.05;       ///< std of translation error per metre travelled
  double odometry_noise_angular = 0.05;      ///< radians of heading error per radian turned
  double odometry_noise_drift = 0.01;        ///< radians of heading error per metre travelled
  double heading_bias = 0.01;                ///< radians of systematic heading error per metre
  double scan_period = 0.2;                  ///< seconds between scans (timestamps)
};

/// One scan from the true robot pose (laser at the robot origin), beams ordered right to left.
LaserScan simulate_scan(const World& world, const slam::Pose2& robot,
                        const SimulationSettings& settings, aco::Rng& rng);

struct SimulatedRun {
  LaserLog log;            ///< scans with noisy odometry (as a CARMEN log would hold them)
  slam::Trajectory truth;  ///< true robot poses, one per scan
};

/// Drives along the waypoints (turning on the spot at corners, then moving straight) starting
/// at the first waypoint facing the second; one scan every `step` metres or `turn_step` radians.
SimulatedRun simulate_run(const World& world, std::span<const Eigen::Vector2d> waypoints,
                          const SimulationSettings& settings, std::uint64_t seed);

}  // namespace antslam::frontend
