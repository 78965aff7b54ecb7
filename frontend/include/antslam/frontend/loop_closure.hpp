#pragma once
// Loop-closure matching of two fragments (paper Sec. III-A): the points of a later fragment b
// are matched against the map of an earlier fragment a over a window of about 3 sigma of how
// well the frontend knows their relative pose. Branch-and-bound correlative search finds the
// best pose exactly (Cartographer's loop-closure matcher, in place of the paper's RANSAM: both
// score candidate alignments on a grid; B&B tries all of them in the window); the closure is
// accepted only if it scores high enough AND no separate second peak comes close (a corridor
// matches itself shifted along its length). Its Gaussian N(mu_H, Sigma_H) is then estimated like
// eqs. (5)-(6), from candidates gathered around H.

#include <Eigen/Core>
#include <optional>
#include <string>

#include "antslam/frontend/distance_field.hpp"
#include "antslam/frontend/likelihood_pyramid.hpp"
#include "antslam/frontend/pose_likelihood.hpp"
#include "antslam/frontend/scan_points.hpp"
#include "antslam/slamgraph/gaussian2.hpp"

namespace antslam::frontend {

struct LoopClosureSettings {
  bool enabled = true;                ///< look for loop closures at all
  double resolution = 0.1;            ///< metres, cell of fragment maps and of the B&B lattice
  double sigma = 0.1;                 ///< metres, likelihood std of closure scores
  int levels = 6;                     ///< B&B pyramid levels (top block 2^(levels-1) cells)
  double point_spacing = 0.1;         ///< metres, thinning of the matched fragment's points
  double max_range = 20.0;            ///< metres; longer readings stay out of fragment maps
  double min_score = 0.6;             ///< mean point likelihood in [0, 1] a closure needs
  double max_second_ratio = 0.9;      ///< reject if a separate peak scores this share of the best
  double exclusion_linear = 1.0;      ///< metres; a "separate" peak lies further than this ...
  double exclusion_angular = 0.3;     ///< ... or turned more than this many radians
  double window_sigmas = 3.0;         ///< window half-width in standard deviations
  double min_window_linear = 1.0;     ///< metres, smallest window half-width in x and y
  double max_window_linear = 8.0;     ///< metres, largest window half-width in x and y
  double min_window_angular = 0.1;    ///< radians, smallest heading half-width
  double max_window_angular = 3.14;   ///< radians, largest heading half-width
  std::size_t min_fragment_gap = 3;   ///< b - a >= this for a candidate pair (a, b)
  std::size_t target_neighbours = 3;  ///< fragments on each side of a that join its target map
                                      ///< (3: leave-one-log-out, docs/generalisation.md)
  double overlap_radius = 3.0;        ///< metres; robot poses this close see the same place
  double min_uncertainty = 0.3;       ///< metres (3 sigma); pairs already known better are skipped
  std::size_t max_attempts = 3;       ///< candidate pairs tried per fragment (nearest first)
  double temperature = 15.0;          ///< divides the closure log-likelihood: 1 is honest on
                                      ///< simulated loops, 15 on real logs (docs/frontend.md)
  PosteriorSettings posterior;        ///< candidate box of eqs. (5)-(6) around H
};

/// Throws std::invalid_argument naming the first nonsensical field.
void validate(const LoopClosureSettings& settings);

/// The map of a fragment used as the target of closure matching (its points in its frame).
class FragmentMap {
 public:
  FragmentMap(const Points& points, const LoopClosureSettings& settings);
  const DistanceField& field() const { return field_; }
  const LikelihoodPyramid& pyramid() const { return pyramid_; }

 private:
  DistanceField field_;
  LikelihoodPyramid pyramid_;
};

struct ClosureMatch {
  bool accepted = false;
  std::string reason;                       ///< why it was rejected, or "accepted"
  double score = 0.0;                       ///< best mean likelihood in [0, 1] (0: nothing found)
  double second_score = 0.0;                ///< best separate peak (0: none above the threshold)
  slam::Pose2 pose;                         ///< F_b in F_a found by the search (refined)
  std::optional<slam::Gaussian2> relative;  ///< eqs. (5)-(6) over F_b in F_a (when accepted)
  std::optional<slam::Gaussian2>
      anchored;  ///< the same over anchor's pose in F_a: N(mu_H, Sigma_H)
};

/// Matches `points` (fragment b, in F_b) against fragment a's map around `prior` (F_b in F_a)
/// with the window of `prior_covariance`; `anchor` is the point of F_b whose pose the closure
/// hypothesis is about (E_b in the paper).
ClosureMatch match_fragments(const FragmentMap& target, const Points& points,
                             const slam::Pose2& prior, const Eigen::Matrix3d& prior_covariance,
                             const slam::Pose2& anchor, const LoopClosureSettings& settings);

}  // namespace antslam::frontend
