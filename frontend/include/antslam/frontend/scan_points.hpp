#pragma once
// Beam end points of a scan, grouped into surfaces, and thinning of point sets.

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

#include "antslam/frontend/laser_log.hpp"
#include "antslam/slamgraph/pose2.hpp"

namespace antslam::frontend {

using Points = std::vector<Eigen::Vector2d>;

/// The end points, in the robot frame, of the beams that returned a hit: readings below
/// `min_range` (noise, the robot's own body) or at or above min(max_range, the sensor's maximum
/// range) ("no return") are dropped. Consecutive points are marked as lying on one surface with
/// the adaptive breakpoint detector (Borges and Aldon 2004): end points at ranges r1 <= r2 are
/// on one surface if at most r1 sin(dphi) / sin(lambda - dphi) apart (dphi: beam step), i.e. on
/// a plane seen at an incidence below 90 deg - lambda.
struct ScanSurfaces {
  Points points;                         ///< metres, robot frame, in beam order
  std::vector<std::uint8_t> joins_next;  ///< 1 if points[k] and points[k + 1] share a surface
};

ScanSurfaces scan_surfaces(const LaserScan& scan, double min_range, double max_range,
                           double lambda);

/// The points that share a surface with a neighbour. Isolated returns (a wall seen at a grazing
/// angle, mixed pixels at depth jumps, a chair leg) are left out: a row of isolated returns on
/// a far wall moves with the robot and would pull a match back onto the previous pose.
Points supported_points(const ScanSurfaces& surfaces);

/// All points plus points every `spacing` metres between neighbours on one surface: walls are
/// continuous in a map made of them.
Points dense_points(const ScanSurfaces& surfaces, double spacing);

/// Keeps the first point of every `spacing` x `spacing` cell, in the input order.
Points thin_points(std::span<const Eigen::Vector2d> points, double spacing);

/// The points moved from a frame into its parent frame: pose * p.
Points transform_points(const slam::Pose2& pose, std::span<const Eigen::Vector2d> points);

}  // namespace antslam::frontend
