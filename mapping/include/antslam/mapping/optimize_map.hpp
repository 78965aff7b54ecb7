#pragma once
// The whole AntSLAM pipeline on a laser log (paper Secs. III-IV): the frontend builds the
// fragment set (scan matching, fragments, loop closures), the optimizer picks the fragments'
// world frames (eq. 10; several independent trials, the lowest weight wins), and every scan's
// corrected pose is its fragment's optimised frame times its pose in the fragment.

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "antslam/frontend/frontend.hpp"
#include "antslam/mapping/close_loops.hpp"
#include "antslam/slamgraph/optimize.hpp"
#include "antslam/slamgraph/trajectory.hpp"

namespace antslam::mapping {

/// The pipeline's optimizer: hybrid (Algorithm 2) + NLopt refinement, otherwise the defaults.
slam::OptimizeSettings default_mapping_optimizer();

struct MappingSettings {
  slam::OptimizeSettings optimize = default_mapping_optimizer();  ///< method and parameters
  std::size_t trials = 20;  ///< independent optimizer trials (count); the lowest weight wins
  std::size_t threads = 1;  ///< threads the trials run on (0 = all cores); results do not
                            ///< depend on it
  aco::BackendKind backend = aco::BackendKind::automatic;  ///< runs the trials in parallel
  ClosingSettings closing;  ///< then close the loops with the trusted closures (close_loops.hpp)
};

/// Throws std::invalid_argument naming the first nonsensical field.
void validate(const MappingSettings& settings);

/// How well a map agrees with one loop closure: the residual of the anchor's pose in F_a
/// against the hypothesis H, and its Mahalanobis distance sqrt(r^T Sigma_H^-1 r).
struct ClosureResidual {
  std::size_t from = 0;      ///< fragment a
  std::size_t to = 0;        ///< fragment b
  slam::Pose2 residual;      ///< anchor pose in F_a minus H (metres, radians; angle wrapped)
  double mahalanobis = 0.0;  ///< sqrt(r^T Sigma_H^-1 r), standard deviations
};

/// The residual of every closure of `set` with the fragments at world poses `frames`.
std::vector<ClosureResidual> closure_residuals(const slam::FragmentSet& set,
                                               std::span<const slam::Pose2> frames);

struct MappingResult {
  std::vector<slam::OptimizeResult> trials;      ///< every trial, in trial order
  std::size_t best = 0;                          ///< trial with the lowest weight (first on ties)
  std::optional<Closing> closing;                ///< the loops closed (when enabled)
  std::vector<slam::Pose2> frames;               ///< the map: the closed frames, else the best
                                                 ///< trial's
  slam::Scores scores;                           ///< eq. (10) and chi2 of the map
  std::vector<slam::Pose2> scan_matcher_frames;  ///< F_i in W from the means mu_i (eq. 8)
  slam::Trajectory corrected;                    ///< every scan's pose in W under the map
  std::vector<ClosureResidual> before;           ///< closures under the scan-matcher frames
  std::vector<ClosureResidual> after;            ///< closures under the map's frames
  slam::Scores scan_matcher;                     ///< eq. (10) and chi2 of the scan-matcher map
  double seconds = 0.0;                          ///< wall-clock time of the optimisation
};

/// Called after each trial with the number of trials finished so far.
using TrialObserver = std::function<void(std::size_t finished)>;

/// Optimises the fragment set of a frontend run: settings.trials trials of
/// settings.optimize.method, trial t seeded with slam::trial_seed(settings.optimize.seed, t);
/// then, if settings.closing.enabled, closes the loops with the trusted closures from the best
/// trial's frames (close_loops.hpp): that is the map.
/// Throws std::invalid_argument if the set has no loop closure (nothing to optimise) or the
/// settings are invalid.
MappingResult optimize_map(const slam::FragmentSet& set, const MappingSettings& settings,
                           const TrialObserver& observer = {});

}  // namespace antslam::mapping
