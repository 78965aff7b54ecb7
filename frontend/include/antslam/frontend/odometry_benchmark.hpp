#pragma once
// A benchmark with ground truth from a corrected log (pose = odom = the corrected pose, as in
// the GMapping-corrected Radish logs): the corrected poses become the reference, odometry is
// derived from them and corrupted with seeded noise (odometry_noise.hpp), and the ODOM messages,
// which hold corrected poses and would leak the reference, are dropped.

#include <cstddef>
#include <cstdint>

#include "antslam/frontend/laser_log.hpp"
#include "antslam/frontend/odometry_noise.hpp"
#include "antslam/slamgraph/trajectory.hpp"

namespace antslam::frontend {

struct OdometryBenchmark {
  LaserLog log;                      ///< the scans with the noisy odometry, no ODOM messages
  slam::Trajectory reference;        ///< the corrected pose of every scan
  slam::Trajectory odometry;         ///< the noisy odometry of every scan
  bool restamped = false;            ///< the scan stamps were re-stamped (restamp_evenly)
  std::size_t dropped_odometry = 0;  ///< ODOM messages dropped
};

/// Scan timestamps that do not strictly increase (csail-corrected prints 6 digits: 365 scans
/// share one) cannot be associated with a reference; they are replaced by evenly spaced ones
/// over the same span (1 s apart if the span is empty). Returns false, and changes nothing, if
/// the stamps increase strictly.
bool restamp_evenly(LaserLog& log);

/// The benchmark of a corrected log with odometry noise `noise` seeded by `seed`. Throws
/// std::invalid_argument for invalid noise.
OdometryBenchmark simulate_odometry(LaserLog corrected, const OdometryNoise& noise,
                                    std::uint64_t seed);

}  // namespace antslam::frontend
