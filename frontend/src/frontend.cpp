#include "antslam/frontend/frontend.hpp"

#include <chrono>
#include <filesystem>

namespace antslam::frontend {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

void validate(const FrontendSettings& settings) {
  validate(settings.matcher);
  validate(settings.fragmentation);
  validate(settings.closure);
}

Frontend::Frontend(const FrontendSettings& settings, std::string name)
    : settings_(settings),
      name_(std::move(name)),
      matcher_(settings.matcher),
      fragmenter_(settings.fragmentation),
      closer_(settings.closure) {}

void Frontend::add_scan(const LaserScan& scan) {
  const auto start = std::chrono::steady_clock::now();
  const MatchResult match = matcher_.add_scan(scan);
  stats_.unmatched += match.status == MatchStatus::too_few_points ? 1U : 0U;
  stats_.recovered += match.status == MatchStatus::recovered ? 1U : 0U;
  stats_.diverged += match.status == MatchStatus::diverged ? 1U : 0U;
  stats_.odometry_along_flat += match.odometry_along_flat ? 1U : 0U;
  records_.push_back(
      {match.status, match.prior_mahalanobis, match.inlier_fraction, match.odometry_along_flat});
  trajectory_.push_back({scan.stamp, match.pose()});
  const bool started =
      fragmenter_.add(stats_.scans, scan.stamp, match.pose(), match.gaussian.covariance());
  ++stats_.scans;
  const std::vector<FragmentRecord>& fragments = fragmenter_.fragments();
  const std::size_t current = fragments.size() - 1;
  // The scan's points in its fragment's frame: matched points and the dense map.
  const ScanMatcherSettings& m = settings_.matcher;
  const LoopClosureSettings& c = settings_.closure;
  const ScanSurfaces surfaces = scan_surfaces(scan, m.min_range, c.max_range, m.surface_incidence);
  const slam::Pose2 in_fragment = slam::between(fragments[current].frame, match.pose());
  closer_.add_points(
      current,
      transform_points(in_fragment, thin_points(supported_points(surfaces), c.point_spacing)),
      transform_points(in_fragment,
                       thin_points(dense_points(surfaces, 0.5 * c.resolution), c.resolution)));
  stats_.matching_seconds += seconds_since(start);
  if (started && current > 0) {
    const auto closing = std::chrono::steady_clock::now();
    closer_.close(current - 1, fragmenter_);
    stats_.closure_seconds += seconds_since(closing);
  }
}

FrontendResult Frontend::finish() {
  FrontendResult result;
  if (!fragmenter_.fragments().empty()) {
    const auto closing = std::chrono::steady_clock::now();
    closer_.close(fragmenter_.fragments().size() - 1, fragmenter_);
    stats_.closure_seconds += seconds_since(closing);
  }
  result.fragment_set = fragmenter_.fragment_set(name_);
  result.fragment_set.closures = closer_.closures();
  result.trajectory = trajectory_;
  result.fragments = fragmenter_.fragments();
  result.attempts = closer_.attempts();
  result.scans = records_;
  result.stats = stats_;
  return result;
}

std::string to_string(const FrontendProgress& p) {
  return "frontend: scan " + std::to_string(p.scan) + "/" + std::to_string(p.scans) +
         ", fragments " + std::to_string(p.fragments) + ", closures " + std::to_string(p.closures);
}

FrontendResult run_frontend(const LaserLog& log, const FrontendSettings& settings,
                            const FrontendObserver& observer) {
  Frontend frontend(settings, std::filesystem::path(log.source).filename().string());
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    frontend.add_scan(log.scans[i]);
    if (observer)
      observer({i + 1, log.scans.size(), frontend.fragment_count(), frontend.closure_count()});
  }
  return frontend.finish();
}

}  // namespace antslam::frontend
