#pragma once
// Loop-closure detection (paper Sec. III-A, after ref. [14]): when a fragment is complete, every
// earlier fragment whose poses the fragment's uncertainty ellipse reaches is a candidate; the
// nearest candidates are matched (match_fragments) against the map of the candidate and its
// neighbours (a few fragments on each side, as the scan matcher placed them: a later visit
// seldom sees exactly what one fragment saw), and the best accepted match becomes a loop
// closure (a, b) with anchor E_b and hypothesis N(mu_H, Sigma_H). Every accepted closure is kept
// (several loops), and each one also shrinks the uncertainty between the places it joins.

#include <Eigen/Core>
#include <cstddef>
#include <deque>
#include <memory>
#include <utility>
#include <vector>

#include "antslam/frontend/fragmenter.hpp"
#include "antslam/frontend/loop_closure.hpp"
#include "antslam/frontend/scan_points.hpp"
#include "antslam/frontend/uncertainty_graph.hpp"
#include "antslam/slamgraph/fragment_set.hpp"

namespace antslam::frontend {

struct ClosureAttempt {
  std::size_t from = 0;      ///< fragment a
  std::size_t to = 0;        ///< fragment b
  double mahalanobis = 0.0;  ///< of the nearest pair of poses (ellipse test), squared
  slam::Pose2 prior;         ///< F_b in F_a before matching (least-uncertain path)
  Eigen::Matrix3d prior_covariance = Eigen::Matrix3d::Zero();  ///< of `prior`
  ClosureMatch match;                                          ///< the outcome
  double seconds = 0.0;                                        ///< time spent matching
};

class LoopCloser {
 public:
  explicit LoopCloser(const LoopClosureSettings& settings);

  /// Adds points seen from fragment `fragment` (its frame): `matched` for matching it against
  /// earlier fragments, `map` for the map it offers to later ones. Fragments come in order.
  void add_points(std::size_t fragment, const Points& matched, const Points& map);

  /// Looks for closures of the complete fragment `b` with earlier fragments.
  void close(std::size_t b, const Fragmenter& fragmenter);

  const std::vector<slam::LoopClosure>& closures() const { return closures_; }
  const std::vector<ClosureAttempt>& attempts() const { return attempts_; }

 private:
  struct Candidate {
    std::size_t from;
    double mahalanobis;
    RelativeEstimate estimate;
  };
  std::vector<Candidate> candidates(std::size_t b, const Fragmenter& fragmenter) const;
  std::vector<GraphEdge> edges(std::size_t b, const Fragmenter& fragmenter) const;
  /// The map that fragment b is matched against for a closure with fragment a: fragments
  /// a - target_neighbours .. a + target_neighbours (none within min_fragment_gap of b) in F_a,
  /// from a small cache (neighbouring fragments try the same targets).
  const FragmentMap& target(std::size_t a, std::size_t b, const Fragmenter& fragmenter);

  LoopClosureSettings settings_;
  std::vector<Points> matched_;  ///< per fragment, thinned
  std::vector<Points> map_;      ///< per fragment, thinned
  std::vector<slam::LoopClosure> closures_;
  std::vector<GraphEdge> closure_edges_;
  std::vector<ClosureAttempt> attempts_;
  /// Target maps by (a, last fragment in it), newest first.
  std::deque<std::pair<std::pair<std::size_t, std::size_t>, std::unique_ptr<FragmentMap>>> cache_;
};

}  // namespace antslam::frontend
