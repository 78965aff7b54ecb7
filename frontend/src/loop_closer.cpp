#include "antslam/frontend/loop_closer.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "antslam/frontend/pose_covariance.hpp"

namespace antslam::frontend {

namespace {

/// chi^2 with 2 degrees of freedom at 99 %: the ellipse of the paper's detection test.
constexpr double kEllipse = 9.21;

/// Fragment maps kept for reuse.
constexpr std::size_t kCachedMaps = 8;

}  // namespace

LoopCloser::LoopCloser(const LoopClosureSettings& settings) : settings_(settings) {
  validate(settings_);
}

void LoopCloser::add_points(std::size_t fragment, const Points& matched, const Points& map) {
  if (fragment >= matched_.size()) {
    matched_.resize(fragment + 1);
    map_.resize(fragment + 1);
  }
  matched_[fragment].insert(matched_[fragment].end(), matched.begin(), matched.end());
  map_[fragment].insert(map_[fragment].end(), map.begin(), map.end());
}

std::vector<GraphEdge> LoopCloser::edges(std::size_t b, const Fragmenter& fragmenter) const {
  std::vector<GraphEdge> out = closure_edges_;
  for (std::size_t i = 0; i < b; ++i)
    out.push_back({i, i + 1, fragmenter.exit(i),
                   fragmenter.settings().covariance_scale * fragmenter.fragments()[i].accumulated});
  return out;
}

std::vector<LoopCloser::Candidate> LoopCloser::candidates(std::size_t b,
                                                          const Fragmenter& fragmenter) const {
  std::vector<Candidate> out;
  if (b < settings_.min_fragment_gap) return out;
  const std::vector<GraphEdge> graph = edges(b, fragmenter);
  const std::vector<RelativeEstimate> estimates = relative_to(b, b + 1, graph);
  const std::vector<FragmentRecord>& fragments = fragmenter.fragments();
  const double overlap = settings_.overlap_radius * settings_.overlap_radius;
  for (std::size_t a = 0; a + settings_.min_fragment_gap <= b; ++a) {
    const RelativeEstimate& e = estimates[a];
    if (!e.reachable) continue;
    const double spread = e.covariance(0, 0) + e.covariance(1, 1);
    if (9.0 * spread < settings_.min_uncertainty * settings_.min_uncertainty) continue;
    // Does b's uncertainty ellipse (grown by the sensor overlap) reach one of a's poses?
    double nearest = std::numeric_limits<double>::infinity();
    for (const slam::StampedPose& p : fragments[b].trajectory) {
      const slam::Pose2 placed = e.pose * p.pose;
      const Eigen::Matrix3d cov =
          compose_covariance(e.pose, e.covariance, p.pose, Eigen::Matrix3d::Zero());
      const Eigen::Matrix2d ellipse =
          cov.topLeftCorner<2, 2>() + overlap * Eigen::Matrix2d::Identity();
      const Eigen::Matrix2d inverse = ellipse.inverse();
      for (const slam::StampedPose& q : fragments[a].trajectory) {
        const Eigen::Vector2d d = q.pose.translation() - placed.translation();
        nearest = std::min(nearest, d.dot(inverse * d));
      }
    }
    if (nearest <= kEllipse) out.push_back({a, nearest, e});
  }
  std::stable_sort(out.begin(), out.end(), [](const Candidate& x, const Candidate& y) {
    return x.mahalanobis < y.mahalanobis;
  });
  return out;
}

const FragmentMap& LoopCloser::target(std::size_t a, std::size_t b, const Fragmenter& fragmenter) {
  // Fragments a - k .. a + k, but none within min_fragment_gap of b (b would match itself).
  const std::size_t first = a - std::min(a, settings_.target_neighbours);
  const std::size_t last =
      std::min(a + settings_.target_neighbours, b - settings_.min_fragment_gap);
  const auto key = std::make_pair(a, last);
  const auto hit = std::find_if(cache_.begin(), cache_.end(),
                                [&](const auto& entry) { return entry.first == key; });
  if (hit != cache_.end()) return *hit->second;
  // The neighbours placed in F_a as the scan matcher placed them (locally accurate).
  const std::vector<FragmentRecord>& fragments = fragmenter.fragments();
  Points points;
  for (std::size_t n = first; n <= last; ++n) {
    const Points moved =
        transform_points(slam::between(fragments[a].frame, fragments[n].frame), map_[n]);
    points.insert(points.end(), moved.begin(), moved.end());
  }
  cache_.emplace_front(
      key, std::make_unique<FragmentMap>(thin_points(points, settings_.resolution), settings_));
  if (cache_.size() > kCachedMaps) cache_.pop_back();
  return *cache_.front().second;
}

void LoopCloser::close(std::size_t b, const Fragmenter& fragmenter) {
  if (b >= matched_.size()) return;
  matched_[b] = thin_points(matched_[b], settings_.point_spacing);
  map_[b] = thin_points(map_[b], settings_.resolution);
  if (!settings_.enabled) return;
  const std::vector<Candidate> found = candidates(b, fragmenter);
  const slam::Pose2 anchor = fragmenter.exit(b);
  std::optional<std::size_t> chosen;
  for (std::size_t k = 0; k < found.size() && k < settings_.max_attempts; ++k) {
    const Candidate& c = found[k];
    const auto start = std::chrono::steady_clock::now();
    ClosureAttempt attempt{
        c.from,
        b,
        c.mahalanobis,
        c.estimate.pose,
        c.estimate.covariance,
        match_fragments(target(c.from, b, fragmenter), matched_[b], c.estimate.pose,
                        c.estimate.covariance, anchor, settings_),
        0.0};
    attempt.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (attempt.match.accepted && (!chosen || attempt.match.score > attempts_[*chosen].match.score))
      chosen = attempts_.size();
    attempts_.push_back(std::move(attempt));
  }
  if (!chosen) return;
  const ClosureAttempt& best = attempts_[*chosen];
  closures_.push_back({best.from, best.to, anchor, *best.match.anchored});
  closure_edges_.push_back(
      {best.from, best.to, best.match.relative->mean(), best.match.relative->covariance()});
}

}  // namespace antslam::frontend
