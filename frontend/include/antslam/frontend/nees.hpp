#pragma once
// Consistency of the scan matcher's Gaussian (eqs. (5)-(6)) on simulated scans: the normalised
// estimation error squared NEES = (x - mu)^T Sigma^-1 (x - mu) of the true pose x averages 3
// (the dimension) when the covariance is honest. The temperature of the likelihood is chosen so.

#include <cstddef>

#include "antslam/frontend/scan_matcher.hpp"
#include "antslam/frontend/simulator.hpp"

namespace antslam::frontend {

struct NeesStats {
  std::size_t count = 0;  ///< matched scans
  double mean = 0.0;      ///< mean NEES (3 when honest)
  double median = 0.0;    ///< median NEES (2.37 for a chi-square with 3 degrees of freedom)
};

/// Matches every scan of the run after the first against a local map that holds the earlier
/// scans at their TRUE poses (so the Gaussian's claim, p(x | z, m) with m known, is what is
/// tested), starting from the odometry prediction, and compares each Gaussian with the truth.
NeesStats simulated_nees(const SimulatedRun& run, const ScanMatcherSettings& settings);

}  // namespace antslam::frontend
