#include "antslam/frontend/loop_closure.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "antslam/frontend/branch_and_bound.hpp"
#include "setting_checks.hpp"

namespace antslam::frontend {

namespace {

std::string format(const char* pattern, double a, double b = 0.0) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, pattern, a, b);
  return buffer;
}

}  // namespace

void validate(const LoopClosureSettings& s) {
  const SettingCheck require{"loop closure"};
  require(positive(s.resolution), "resolution", "must be positive");
  require(positive(s.sigma), "sigma", "must be positive");
  require(s.levels >= 1 && s.levels <= 12, "levels", "must be in [1, 12]");
  require(positive(s.point_spacing), "point_spacing", "must be positive");
  require(positive(s.max_range), "max_range", "must be positive");
  require(s.min_score > 0.0 && s.min_score <= 1.0, "min_score", "must be in (0, 1]");
  require(s.max_second_ratio > 0.0 && s.max_second_ratio <= 1.0, "max_second_ratio",
          "must be in (0, 1]");
  require(s.exclusion_linear >= 0.0 && s.exclusion_angular >= 0.0, "exclusion", "must be >= 0");
  require(positive(s.window_sigmas), "window_sigmas", "must be positive");
  require(s.min_window_linear >= 0.0 && s.max_window_linear >= s.min_window_linear &&
              s.max_window_linear <= 50.0,
          "window linear limits", "must be ordered and at most 50 m");
  require(s.min_window_angular >= 0.0 && s.max_window_angular >= s.min_window_angular &&
              s.max_window_angular <= 3.1416,
          "window angular limits", "must be ordered and at most pi");
  require(s.min_fragment_gap >= 1, "min_fragment_gap", "must be at least 1");
  require(s.target_neighbours <= 20, "target_neighbours", "must be at most 20");
  require(s.overlap_radius >= 0.0 && std::isfinite(s.overlap_radius), "overlap_radius",
          "must be >= 0");
  require(s.min_uncertainty >= 0.0 && std::isfinite(s.min_uncertainty), "min_uncertainty",
          "must be >= 0");
  require(positive(s.temperature), "temperature", "must be positive");
}

namespace {

DistanceField field_of(const Points& points, const LoopClosureSettings& settings) {
  DistanceField field(settings.resolution, 3.0 * settings.sigma);
  field.insert(points);
  return field;
}

}  // namespace

FragmentMap::FragmentMap(const Points& points, const LoopClosureSettings& settings)
    : field_(field_of(points, settings)), pyramid_(field_, settings.sigma, settings.levels) {}

ClosureMatch match_fragments(const FragmentMap& target, const Points& points,
                             const slam::Pose2& prior, const Eigen::Matrix3d& prior_covariance,
                             const slam::Pose2& anchor, const LoopClosureSettings& s) {
  ClosureMatch out;
  out.pose = prior;
  if (points.empty()) {
    out.reason = "no points to match";
    return out;
  }
  // The window: about 3 sigma of the prior, within limits; headings finer for far points.
  const auto half = [&](int k, double lo, double hi) {
    return std::clamp(s.window_sigmas * std::sqrt(std::max(prior_covariance(k, k), 0.0)), lo, hi);
  };
  double reach = 0.0;
  for (const Eigen::Vector2d& p : points) reach = std::max(reach, p.norm());
  const double step = std::clamp(s.resolution / std::max(reach, 1.0), 1e-3, 0.05);
  const SearchBox box{prior, half(0, s.min_window_linear, s.max_window_linear),
                      half(1, s.min_window_linear, s.max_window_linear),
                      half(2, s.min_window_angular, s.max_window_angular), step};
  // Only poses that could be accepted are searched for: the bound prunes far more.
  const std::optional<ScoredPose> best =
      branch_and_bound(target.pyramid(), points, box, s.min_score);
  if (!best) {
    out.reason = format("no pose in the window scores %.3f", s.min_score);
    return out;
  }
  out.score = best->score;
  out.pose = best->pose;
  // A separate peak almost as good: the place is ambiguous (corridor, repeated rooms).
  const std::optional<ScoredPose> second =
      branch_and_bound(target.pyramid(), points, box, s.max_second_ratio * best->score,
                       Exclusion{best->pose, s.exclusion_linear, s.exclusion_angular});
  if (second) {
    out.second_score = second->score;
    out.reason = format("ambiguous: a separate peak scores %.3f of the best %.3f", second->score,
                        best->score);
    return out;
  }
  const Refinement refined =
      refine_pose(target.field(), points, best->pose, 10, 2.0 * s.resolution, 2.0 * step);
  const LikelihoodModel model{s.sigma, s.temperature};
  const PosteriorSamples samples =
      posterior_samples(target.field(), model, points, refined.pose,
                        laplace_covariance(refined.hessian, model, s.posterior), s.posterior);
  out.pose = refined.pose;
  out.relative = posterior_gaussian(samples);
  out.anchored = posterior_gaussian(samples, anchor);
  out.accepted = true;
  out.reason = "accepted";
  return out;
}

}  // namespace antslam::frontend
