#pragma once
// The laser frontend (paper Sec. III-A) from a log to a fragment set: scan matching with the
// Gaussian of eqs. (5)-(6), fragments every few metres with alignment Gaussians and samples
// (eq. (7)), and loop closures with hypotheses N(mu_H, Sigma_H).

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "antslam/frontend/fragmenter.hpp"
#include "antslam/frontend/laser_log.hpp"
#include "antslam/frontend/loop_closer.hpp"
#include "antslam/frontend/scan_matcher.hpp"
#include "antslam/slamgraph/fragment_set.hpp"
#include "antslam/slamgraph/trajectory.hpp"

namespace antslam::frontend {

struct FrontendSettings {
  ScanMatcherSettings matcher;          ///< scan matching (eqs. (5)-(6))
  FragmentationSettings fragmentation;  ///< fragments and samples (eq. (7))
  LoopClosureSettings closure;          ///< loop-closure detection and matching
};

/// Throws std::invalid_argument naming the first nonsensical field.
void validate(const FrontendSettings& settings);

struct FrontendStats {
  std::size_t scans = 0;      ///< scans processed
  std::size_t unmatched = 0;  ///< scans that kept the odometry (too few points)
  std::size_t recovered = 0;  ///< scans matched in the wide recovery window
  std::size_t diverged = 0;   ///< scans whose match contradicted the odometry: odometry kept
  std::size_t odometry_along_flat = 0;  ///< scans flatter than the odometry in a direction
  double matching_seconds = 0.0;        ///< wall time of scan matching and fragmentation
  double closure_seconds = 0.0;         ///< wall time of loop-closure detection and matching
};

/// How the scan matcher placed one scan.
struct ScanRecord {
  MatchStatus status = MatchStatus::first_scan;  ///< matched, recovered, or an odometry fallback
  double prior_mahalanobis = 0.0;    ///< distance of the match from the odometry prediction (std)
  double inlier_fraction = 0.0;      ///< share of the scan's points that fit the local map
  bool odometry_along_flat = false;  ///< the odometry kept the estimate along a flat direction
  /// The scan matcher placed it (not an odometry fallback; the first scan counts as placed).
  bool matched_by_scan() const {
    return status != MatchStatus::too_few_points && status != MatchStatus::diverged;
  }
};

struct FrontendResult {
  slam::FragmentSet fragment_set;         ///< fragments, alignments, samples, closures
  slam::Trajectory trajectory;            ///< scan-matcher robot poses in W (first pose = 0)
  std::vector<FragmentRecord> fragments;  ///< which scans each fragment holds, its frame in W
  std::vector<ClosureAttempt> attempts;   ///< every closure candidate matched, accepted or not
  std::vector<ScanRecord> scans;          ///< per scan of the log, in order
  FrontendStats stats;
};

class Frontend {
 public:
  /// `name` goes into the fragment set (e.g. the log's file name).
  Frontend(const FrontendSettings& settings, std::string name);

  /// Processes the next scan of the log.
  void add_scan(const LaserScan& scan);

  /// Looks for closures of the last fragment and returns everything.
  FrontendResult finish();

  std::size_t fragment_count() const { return fragmenter_.fragments().size(); }
  std::size_t closure_count() const { return closer_.closures().size(); }

 private:
  FrontendSettings settings_;
  std::string name_;
  ScanMatcher matcher_;
  Fragmenter fragmenter_;
  LoopCloser closer_;
  slam::Trajectory trajectory_;
  std::vector<ScanRecord> records_;
  FrontendStats stats_;
};

/// Where run_frontend is, after each scan.
struct FrontendProgress {
  std::size_t scan = 0;       ///< scans processed so far
  std::size_t scans = 0;      ///< scans in the log
  std::size_t fragments = 0;  ///< fragments started so far
  std::size_t closures = 0;   ///< loop closures accepted so far
};
using FrontendObserver = std::function<void(const FrontendProgress&)>;

/// "frontend: scan 12/225, fragments 3, closures 1", for progress lines.
std::string to_string(const FrontendProgress& progress);

/// Runs the frontend over a whole log; the fragment set is named after the log's file name.
FrontendResult run_frontend(const LaserLog& log, const FrontendSettings& settings,
                            const FrontendObserver& observer = {});

}  // namespace antslam::frontend
