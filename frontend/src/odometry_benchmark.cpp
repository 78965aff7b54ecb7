#include "antslam/frontend/odometry_benchmark.hpp"

#include <utility>
#include <vector>

#include "antslam/aco/random.hpp"

namespace antslam::frontend {

bool restamp_evenly(LaserLog& log) {
  auto& scans = log.scans;
  bool increasing = true;
  for (std::size_t i = 1; i < scans.size(); ++i) increasing &= scans[i].stamp > scans[i - 1].stamp;
  if (increasing || scans.empty()) return false;
  const double first = scans.front().stamp;
  const double span = scans.back().stamp - first;
  const double period = span > 0.0 ? span / static_cast<double>(scans.size() - 1) : 1.0;
  for (std::size_t i = 0; i < scans.size(); ++i)
    scans[i].stamp = first + static_cast<double>(i) * period;
  return true;
}

OdometryBenchmark simulate_odometry(LaserLog corrected, const OdometryNoise& noise,
                                    std::uint64_t seed) {
  validate(noise);
  OdometryBenchmark b;
  b.log = std::move(corrected);
  b.restamped = restamp_evenly(b.log);
  std::vector<slam::Pose2> poses;
  for (const LaserScan& scan : b.log.scans) {
    poses.push_back(scan.odometry);
    b.reference.push_back({scan.stamp, scan.odometry});
  }
  aco::Rng rng(aco::mix_seed(seed, 0x0D0));
  const std::vector<slam::Pose2> odometry = noisy_odometry(poses, noise, rng);
  for (std::size_t i = 0; i < b.log.scans.size(); ++i) {
    b.log.scans[i].odometry = odometry[i];
    b.odometry.push_back({b.log.scans[i].stamp, odometry[i]});
  }
  b.dropped_odometry = b.log.odometry.size();
  b.log.odometry.clear();
  return b;
}

}  // namespace antslam::frontend
