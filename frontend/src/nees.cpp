#include "antslam/frontend/nees.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace antslam::frontend {

NeesStats simulated_nees(const SimulatedRun& run, const ScanMatcherSettings& settings) {
  if (run.log.scans.size() != run.truth.size() || run.truth.size() < 2)
    throw std::invalid_argument("simulated_nees: need a run with at least two scans");
  ScanMatcher matcher(settings);
  matcher.insert(map_points(run.log.scans[0], settings), run.truth[0].pose);
  std::vector<double> nees;
  for (std::size_t k = 1; k < run.truth.size(); ++k) {
    const LaserScan& scan = run.log.scans[k];
    const slam::Pose2 prediction =
        run.truth[k - 1].pose * slam::between(run.log.scans[k - 1].odometry, scan.odometry);
    const MatchResult r = matcher.match(matching_points(scan, settings), prediction);
    nees.push_back(r.gaussian.mahalanobis_squared(run.truth[k].pose));
    matcher.insert(map_points(scan, settings), run.truth[k].pose);
  }
  NeesStats stats;
  stats.count = nees.size();
  for (const double v : nees) stats.mean += v / static_cast<double>(nees.size());
  std::nth_element(nees.begin(), nees.begin() + static_cast<std::ptrdiff_t>(nees.size() / 2),
                   nees.end());
  stats.median = nees[nees.size() / 2];
  return stats;
}

}  // namespace antslam::frontend
