#pragma once
// The incremental scan matcher (paper Sec. III-A, refs [14], [21]): each scan is matched against
// a local map of the recent scans around the odometry prediction, coarse to fine, and gets the
// Gaussian of eqs. (5)-(6).
//
// Local map: submaps of the likelihood field (distance fields at a coarse and a fine
// resolution). A new submap starts every half `local_map_length` metres travelled; every scan
// goes into the live submaps; a scan is matched against the oldest live submap, which holds
// between half and all of the last `local_map_length` metres, and submaps older than that are
// dropped (Cartographer's scheme). Matching: exhaustive correlative search on the coarse field
// over the search window; around each of the best few coarse peaks, the same on the fine field;
// Levenberg-Marquardt on the interpolated fine field from the best; then eqs. (5)-(6). A poor
// fit (odometry stall or jump) triggers a search of a wide recovery window.
//
// The odometry is the prior (odometry_prior.hpp): its step covariance widens the search window
// for long steps; a match further from the prediction than divergence_sigmas that fits fewer
// than trusted_fit of its points is a wrong peak, and the scan keeps the odometry prediction
// with an inflated covariance; otherwise the match is fused with the prediction, so that along
// a direction the scan cannot pin down (a corridor) the odometry keeps the estimate.

#include <cstddef>
#include <deque>
#include <optional>
#include <string_view>

#include "antslam/frontend/correlative_search.hpp"
#include "antslam/frontend/distance_field.hpp"
#include "antslam/frontend/laser_log.hpp"
#include "antslam/frontend/odometry_prior.hpp"
#include "antslam/frontend/pose_likelihood.hpp"
#include "antslam/frontend/scan_points.hpp"
#include "antslam/slamgraph/gaussian2.hpp"

namespace antslam::frontend {

struct ScanMatcherSettings {
  double min_range = 0.1;             ///< metres; shorter readings are dropped
  double max_range = 30.0;            ///< metres; longer readings stay out of the map
  double max_match_range = 20.0;      ///< metres; longer readings are not matched (the map
                                      ///< reaches further, so no edge of the map pulls a scan)
  double surface_incidence = 0.17;    ///< radians, lambda of scan_surfaces (10 deg): hits of
                                      ///< one surface are joined in the map, lone hits not matched
  double resolution = 0.05;           ///< metres, fine likelihood-field cell
  double sigma = 0.05;                ///< metres, fine likelihood-field std
  double coarse_resolution = 0.15;    ///< metres, coarse likelihood-field cell
  double coarse_sigma = 0.2;          ///< metres, coarse likelihood-field std
  double point_spacing = 0.1;         ///< metres, scan thinning for matching
  double linear_window = 0.5;         ///< metres, search half-width around the prediction (at
                                      ///< least; window_sigmas of a long step can widen it)
  double angular_window = 0.35;       ///< radians, search half-width around the prediction (at
                                      ///< least)
  double window_sigmas = 3.0;         ///< the window spans this many odometry-step std
  double max_linear_window = 3.0;     ///< metres, widest search half-width
  double coarse_angular_step = 0.02;  ///< radians between headings of the coarse search
  double fine_angular_step = 0.004;   ///< radians between headings of the fine search
  std::size_t coarse_peaks = 3;       ///< best coarse peaks refined on the fine field
  double prior_weight = 0.01;         ///< m^2, odometry prior at the window edge (PosePrior)
  bool refine = true;                 ///< Gauss-Newton after the fine search
  double inlier_distance = 0.1;       ///< metres; a matched point this close to a hit fits
  double recovery_fraction = 0.5;     ///< fewer fitting points: search the recovery window too
  double recovery_gain = 0.25;        ///< share of points the recovery must fit in addition
  double recovery_linear_window = 1.0;   ///< metres, half-width of the recovery search
  double recovery_angular_window = 1.6;  ///< radians, half-width of the recovery search
  double temperature = 0.2;              ///< divides the log-likelihood (calibrated: NEES ~ 3 on
                                         ///< simulated scans, docs/frontend.md)
  double local_map_length = 10.0;        ///< metres of travel a submap spans
  std::size_t min_points = 20;           ///< fewer matching points: keep the odometry prediction
  OdometryPrior odometry;                ///< step covariance of the odometry (the prior)
  double divergence_sigmas = 4.0;        ///< a match further from the prediction (Mahalanobis, step
                                   ///< covariance plus the match's) contradicts the odometry ...
  double trusted_fit = 0.8;         ///< ... and is kept only if this share of its points fit
  double fallback_inflation = 4.0;  ///< multiplies the step covariance when the odometry is kept
  PosteriorSettings posterior;      ///< candidate box of eqs. (5)-(6)
};

/// Throws std::invalid_argument naming the first nonsensical field.
void validate(const ScanMatcherSettings& settings);

/// How a scan's pose was found.
enum class MatchStatus {
  first_scan,      ///< the first scan defines the frame
  matched,         ///< matched in the window around the odometry prediction
  recovered,       ///< matched in the wide recovery window (the odometry had failed)
  too_few_points,  ///< fewer than min_points to match: the odometry prediction, inflated
  diverged,        ///< the match contradicted the odometry without fitting well enough to
                   ///< overrule it (a wrong peak): the odometry prediction, inflated
};

std::string_view to_string(MatchStatus status);

struct MatchResult {
  slam::Gaussian2 gaussian;  ///< N(mu, Sigma) of the robot pose in the matcher's frame
  slam::Pose2 best;          ///< the most likely pose found (the centre of eqs. (5)-(6))
  MatchStatus status = MatchStatus::first_scan;  ///< how the pose was found
  bool odometry_along_flat = false;  ///< the scan was flatter than the odometry in a direction:
                                     ///< the fused estimate follows the odometry along it
  double prior_mahalanobis = 0.0;    ///< distance of the match from the odometry prediction
                                     ///< (standard deviations; 0 without a prediction)
  double mean_distance = 0.0;        ///< metres, RMS distance of the points to the map at mu
  double inlier_fraction = 0.0;      ///< share of points within inlier_distance of a map hit at mu
  std::size_t points = 0;            ///< points used for matching
  const slam::Pose2& pose() const { return gaussian.mean(); }
  /// The scan's own match gave the pose (not the odometry).
  bool matched() const {
    return status == MatchStatus::matched || status == MatchStatus::recovered;
  }
};

/// The points of a scan that are matched (robot frame): returns on a surface, within
/// max_match_range, thinned to point_spacing.
Points matching_points(const LaserScan& scan, const ScanMatcherSettings& settings);

/// The points of a scan that go into the local map (robot frame): its surfaces, densely.
Points map_points(const LaserScan& scan, const ScanMatcherSettings& settings);

class ScanMatcher {
 public:
  explicit ScanMatcher(const ScanMatcherSettings& settings);

  /// Matches the next scan of a log and adds it to the local map. The first scan defines the
  /// frame: its robot pose is the origin.
  MatchResult add_scan(const LaserScan& scan);

  /// The pose and Gaussian of a scan's matching points (robot frame) against the current local
  /// map, searching around `prediction` within window_sigmas of `prediction_covariance` (W
  /// axes; at least the settings' window); the map is not changed (apart from growing its
  /// grids). The odometry checks are add_scan's.
  MatchResult match(const Points& points, const slam::Pose2& prediction,
                    const Eigen::Matrix3d& prediction_covariance = Eigen::Matrix3d::Zero());

  /// The match checked against the odometry prediction N(prediction) (W axes): within
  /// divergence_sigmas it is fused with the prediction; further off it is kept as it is if at
  /// least trusted_fit of its points fit (it overrules a failed odometry), else the scan takes
  /// the prediction with fallback_inflation times its covariance (status diverged).
  MatchResult check_against(MatchResult match, const slam::Gaussian2& prediction) const;

  /// Adds map points (robot frame) seen from `pose` to the local map.
  void insert(const Points& points, const slam::Pose2& pose);

  const ScanMatcherSettings& settings() const { return settings_; }

 private:
  struct Submap {
    DistanceField fine;
    DistanceField coarse;
    double start = 0.0;  ///< metres travelled when it was started
  };
  void start_submap();
  /// Coarse search, fine search and Gauss-Newton against the matching submap.
  Refinement search(const Points& points, const slam::Pose2& center, double linear, double angular);

  ScanMatcherSettings settings_;
  std::deque<Submap> submaps_;
  std::optional<slam::Pose2> last_pose_;
  slam::Pose2 last_odometry_;
  double travelled_ = 0.0;
};

}  // namespace antslam::frontend
