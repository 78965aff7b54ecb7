#pragma once
// The noise a pose graph shows, per axis, against the noise it states. Public graphs state
// covariances six times too wide (manhattan3500, intel, city10000), too narrow, or wrong in one
// axis only; PCM's pairwise test (consistency.hpp) and its chi-square checks hinge on them. The
// estimate: every stated covariance Sigma taken as D Sigma D, D = diag(s_xy, s_xy, s_theta), and
// (s_xy, s_theta) the maximum-likelihood scale of the short cycles of nearby closure pairs, the
// cycles that go through the fewest odometry steps and so stay in the linear regime.
//
// False closures must not steer it. True closures come in runs along revisited places: a true
// closure and its neighbour close a cycle of a few steps, while a false closure's nearest
// partner is as far as chance puts it; so only the shortest tenth of the candidate cycles is used
// (with 1,000 random false closures on 423 true ones, the candidates are mostly false, the
// shortest tenth mostly true). Pairs with a false closure give large distances; the estimate
// starts from a low quantile of the distances at the stated noise, then alternates
// keeping the cycles within the chi-square threshold at the current scale and the Gaussian
// maximum likelihood of the scale on them (concentration steps, as in least trimmed squares),
// with the truncation's shrinkage corrected, until the scale stops moving.

#include <cstddef>

#include "antslam/slamgraph/chain.hpp"
#include "antslam/slamgraph/consistency.hpp"
#include "antslam/slamgraph/g2o.hpp"

namespace antslam::slam {

/// Standard-deviation multipliers of every stated covariance: Sigma -> D Sigma D with
/// D = diag(xy, xy, theta).
struct NoiseScale {
  double xy = 1.0;     ///< of the x and y axes
  double theta = 1.0;  ///< of the heading
};

struct ShownNoiseSettings {
  std::size_t partners = 5;       ///< per closure: the short cycles it joins (count)
  std::size_t window = 32;        ///< candidate partners on each side, in (lo, hi) order (count)
  double shortest = 0.1;          ///< of those cycles, this fraction with the least heading
                                  ///< variance, (0, 1]
  std::size_t min_shortest = 50;  ///< but at least this many (count)
  double confidence = 0.99;       ///< chi-square (3 dof) probability of the trimming threshold
  double start_quantile = 0.1;    ///< the start: this quantile of the distances at the stated noise
  std::size_t min_cycles = 10;    ///< fewer kept cycles than this: the stated noise is kept (count)
  std::size_t max_rounds = 30;    ///< concentration steps at most (count)
};

struct ShownNoise {
  NoiseScale scale;         ///< the estimate; {1, 1} (the stated noise) when not estimated
  bool estimated = false;   ///< false when the graph has too few short cycles
  std::size_t cycles = 0;   ///< short cycles examined
  std::size_t inliers = 0;  ///< of them, within the threshold at the estimate
  std::size_t rounds = 0;   ///< concentration steps run
};

/// Throws std::invalid_argument for settings out of range (a confidence or quantile outside
/// (0, 1), a shortest fraction outside (0, 1], no partner, no window).
ShownNoise estimate_shown_noise(const PoseGraph& graph, const ChainSplit& split,
                                const ShownNoiseSettings& settings = {});

/// The graph with every covariance at `scale`, Sigma -> D Sigma D: every information matrix
/// D^-1 I D^-1. Throws std::invalid_argument for a scale that is not positive and finite.
PoseGraph at_noise_scale(const PoseGraph& graph, NoiseScale scale);

}  // namespace antslam::slam
