#include "antslam/frontend/scan_matcher.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "antslam/frontend/pose_covariance.hpp"
#include "setting_checks.hpp"

namespace antslam::frontend {

std::string_view to_string(MatchStatus status) {
  switch (status) {
    case MatchStatus::first_scan:
      return "first scan";
    case MatchStatus::matched:
      return "matched";
    case MatchStatus::recovered:
      return "recovered";
    case MatchStatus::too_few_points:
      return "too few points";
    case MatchStatus::diverged:
      return "diverged";
  }
  return "?";
}

void validate(const ScanMatcherSettings& s) {
  const SettingCheck require{"scan matcher"};
  require(s.min_range >= 0.0 && std::isfinite(s.min_range), "min_range", "must be >= 0");
  require(positive(s.max_range) && s.max_range > s.min_range, "max_range",
          "must be positive and above min_range");
  require(positive(s.max_match_range) && s.max_match_range > s.min_range, "max_match_range",
          "must be positive and above min_range");
  require(s.surface_incidence >= 0.0 && s.surface_incidence < 1.6, "surface_incidence",
          "must be in [0, pi / 2)");
  require(positive(s.resolution), "resolution", "must be positive");
  require(positive(s.sigma), "sigma", "must be positive");
  require(positive(s.coarse_resolution) && s.coarse_resolution >= s.resolution, "coarse_resolution",
          "must be positive and at least the fine resolution");
  require(positive(s.coarse_sigma), "coarse_sigma", "must be positive");
  require(positive(s.point_spacing), "point_spacing", "must be positive");
  require(s.linear_window >= 0.0 && s.linear_window <= 10.0, "linear_window",
          "must be in [0, 10] m");
  require(s.angular_window >= 0.0 && s.angular_window <= 3.2, "angular_window",
          "must be in [0, pi]");
  require(positive(s.window_sigmas), "window_sigmas", "must be positive");
  require(s.max_linear_window >= s.linear_window && s.max_linear_window <= 10.0,
          "max_linear_window", "must be in [linear_window, 10] m");
  require(positive(s.coarse_angular_step), "coarse_angular_step", "must be positive");
  require(positive(s.fine_angular_step), "fine_angular_step", "must be positive");
  require(s.coarse_peaks >= 1 && s.coarse_peaks <= 20, "coarse_peaks", "must be in [1, 20]");
  require(positive(s.temperature), "temperature", "must be positive");
  require(s.prior_weight >= 0.0 && std::isfinite(s.prior_weight), "prior_weight", "must be >= 0");
  require(positive(s.local_map_length), "local_map_length", "must be positive");
  validate(s.odometry);
  require(positive(s.divergence_sigmas), "divergence_sigmas", "must be positive");
  require(s.trusted_fit >= 0.0 && s.trusted_fit <= 1.0, "trusted_fit", "must be in [0, 1]");
  require(s.fallback_inflation >= 1.0 && std::isfinite(s.fallback_inflation), "fallback_inflation",
          "must be >= 1");
  require(positive(s.inlier_distance), "inlier_distance", "must be positive");
  require(s.recovery_fraction >= 0.0 && s.recovery_fraction <= 1.0, "recovery_fraction",
          "must be in [0, 1]");
  require(s.recovery_gain >= 0.0 && s.recovery_gain <= 1.0, "recovery_gain", "must be in [0, 1]");
  require(s.recovery_linear_window >= 0.0 && s.recovery_linear_window <= 10.0,
          "recovery_linear_window", "must be in [0, 10] m");
  require(s.recovery_angular_window >= 0.0 && s.recovery_angular_window <= 3.2,
          "recovery_angular_window", "must be in [0, pi]");
  const PosteriorSettings& p = s.posterior;
  require(p.steps >= 1 && p.steps <= 10, "posterior.steps", "must be in [1, 10]");
  require(p.rounds >= 1 && p.rounds <= 10, "posterior.rounds", "must be in [1, 10]");
  require(positive(p.min_linear) && p.max_linear >= p.min_linear, "posterior linear limits",
          "must be positive and ordered");
  require(positive(p.min_angular) && p.max_angular >= p.min_angular, "posterior angular limits",
          "must be positive and ordered");
}

Points matching_points(const LaserScan& scan, const ScanMatcherSettings& s) {
  const ScanSurfaces surfaces =
      scan_surfaces(scan, s.min_range, s.max_match_range, s.surface_incidence);
  return thin_points(supported_points(surfaces), s.point_spacing);
}

Points map_points(const LaserScan& scan, const ScanMatcherSettings& s) {
  const ScanSurfaces surfaces = scan_surfaces(scan, s.min_range, s.max_range, s.surface_incidence);
  return thin_points(dense_points(surfaces, 0.5 * s.resolution), s.resolution);
}

ScanMatcher::ScanMatcher(const ScanMatcherSettings& settings) : settings_(settings) {
  validate(settings_);
  start_submap();
}

void ScanMatcher::start_submap() {
  // A distance field holds distances up to 3 sigma: beyond, a Gaussian likelihood is flat.
  submaps_.push_back(
      Submap{DistanceField(settings_.resolution, 3.0 * settings_.sigma),
             DistanceField(settings_.coarse_resolution, 3.0 * settings_.coarse_sigma), travelled_});
}

namespace {

/// Share of points within `distance` of a map hit.
double inlier_fraction(const DistanceField& field, const Points& points, const slam::Pose2& pose,
                       double distance) {
  std::size_t inside = 0;
  for (const Eigen::Vector2d& p : points)
    inside += field.interpolate(pose * p) < distance ? 1U : 0U;
  return static_cast<double>(inside) / static_cast<double>(std::max<std::size_t>(1, points.size()));
}

}  // namespace

Refinement ScanMatcher::search(const Points& points, const slam::Pose2& center, double linear,
                               double angular) {
  const ScanMatcherSettings& s = settings_;
  Submap& map = submaps_.front();
  const PosePrior prior{center, std::max(linear, s.resolution),
                        std::max(angular, s.fine_angular_step), s.prior_weight};
  // The coarse field can rank peaks wrongly (cells 3x larger, wider kernel): each of the best
  // coarse peaks is searched on the fine field and the best fine result wins.
  const std::vector<SearchResult> coarse = correlative_peaks(
      map.coarse, points, center, {linear, angular, s.coarse_angular_step}, prior, s.coarse_peaks);
  SearchResult fine{center, 0.0, std::numeric_limits<double>::infinity()};
  for (const SearchResult& peak : coarse) {
    const SearchResult candidate = correlative_search(
        map.fine, points, peak.pose,
        {1.5 * s.coarse_resolution, 2.0 * s.coarse_angular_step, s.fine_angular_step}, prior);
    if (candidate.score < fine.score) fine = candidate;
  }
  return refine_pose(map.fine, points, fine.pose, s.refine ? 20 : 0, 2.0 * s.resolution,
                     4.0 * s.fine_angular_step);
}

MatchResult ScanMatcher::match(const Points& points, const slam::Pose2& prediction,
                               const Eigen::Matrix3d& prediction_covariance) {
  const ScanMatcherSettings& s = settings_;
  const DistanceField& fine = submaps_.front().fine;
  // The window covers window_sigmas of the prediction's uncertainty, at least the settings'.
  const double linear_std =
      std::sqrt(std::max(prediction_covariance(0, 0), prediction_covariance(1, 1)));
  const double linear =
      std::clamp(s.window_sigmas * linear_std, s.linear_window, s.max_linear_window);
  const double angular = std::clamp(s.window_sigmas * std::sqrt(prediction_covariance(2, 2)),
                                    s.angular_window, std::numbers::pi);
  Refinement best = search(points, prediction, linear, angular);
  const double fit = inlier_fraction(fine, points, best.pose, s.inlier_distance);
  MatchResult result;
  result.status = MatchStatus::matched;
  if (fit < s.recovery_fraction) {
    // A poor fit: the odometry may have failed (a stall, a jump); search a wide window.
    const Refinement wide = search(points, prediction, std::max(linear, s.recovery_linear_window),
                                   std::max(angular, s.recovery_angular_window));
    const double wide_fit = inlier_fraction(fine, points, wide.pose, s.inlier_distance);
    if (wide_fit >= fit + s.recovery_gain) {
      best = wide;
      result.status = MatchStatus::recovered;
    }
  }
  const LikelihoodModel model{s.sigma, s.temperature};
  const Eigen::Matrix3d guess = laplace_covariance(best.hessian, model, s.posterior);
  result.gaussian =
      posterior_gaussian(posterior_samples(fine, model, points, best.pose, guess, s.posterior));
  result.best = best.pose;
  result.points = points.size();
  result.mean_distance = std::sqrt(squared_distance(fine, points, result.pose()) /
                                   static_cast<double>(std::max<std::size_t>(1, points.size())));
  result.inlier_fraction = inlier_fraction(fine, points, result.pose(), s.inlier_distance);
  return result;
}

MatchResult ScanMatcher::check_against(MatchResult match, const slam::Gaussian2& prediction) const {
  const ScanMatcherSettings& s = settings_;
  const Eigen::Vector3d r = prediction.residual(match.pose());
  const Eigen::Matrix3d both = prediction.covariance() + match.gaussian.covariance();
  match.prior_mahalanobis = std::sqrt(r.dot(both.ldlt().solve(r)));
  if (match.prior_mahalanobis <= s.divergence_sigmas) {
    match.odometry_along_flat = flatter_than(match.gaussian, prediction);
    match.gaussian = fuse(match.gaussian, prediction);
  } else if (match.inlier_fraction < s.trusted_fit) {
    match.status = MatchStatus::diverged;
    match.gaussian =
        slam::Gaussian2(prediction.mean(), s.fallback_inflation * prediction.covariance());
  }
  return match;
}

void ScanMatcher::insert(const Points& points, const slam::Pose2& pose) {
  const Points world = transform_points(pose, points);
  for (Submap& submap : submaps_) {
    submap.fine.insert(world);
    submap.coarse.insert(world);
  }
}

MatchResult ScanMatcher::add_scan(const LaserScan& scan) {
  const ScanMatcherSettings& s = settings_;
  const Points thinned = matching_points(scan, s);
  MatchResult result;
  if (!last_pose_) {
    result.gaussian = slam::Gaussian2(slam::Pose2{}, Eigen::Matrix3d::Identity() * 1e-12);
  } else {
    // Odometry prediction: the last estimate moved by the odometry increment, with the step's
    // covariance in W axes.
    const slam::Pose2 motion = slam::between(last_odometry_, scan.odometry);
    const slam::Gaussian2 prediction(
        *last_pose_ * motion, compose_covariance(*last_pose_, Eigen::Matrix3d::Zero(), motion,
                                                 step_covariance(s.odometry, motion)));
    if (thinned.size() >= s.min_points) {
      result =
          check_against(match(thinned, prediction.mean(), prediction.covariance()), prediction);
    } else {
      result.status = MatchStatus::too_few_points;
      result.gaussian =
          slam::Gaussian2(prediction.mean(), s.fallback_inflation * prediction.covariance());
      result.points = thinned.size();
    }
    travelled_ += std::hypot(result.pose().x - last_pose_->x, result.pose().y - last_pose_->y);
  }
  // Submaps: a new one every half local-map length; drop those spanning more than the length.
  if (travelled_ - submaps_.back().start >= 0.5 * s.local_map_length) start_submap();
  while (submaps_.size() > 1 && travelled_ - submaps_.front().start >= s.local_map_length)
    submaps_.pop_front();
  insert(map_points(scan, s), result.pose());
  last_pose_ = result.pose();
  last_odometry_ = scan.odometry;
  return result;
}

}  // namespace antslam::frontend
