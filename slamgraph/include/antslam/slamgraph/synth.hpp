#pragma once
// Synthetic fragment sets with known ground truth, for tests, benchmarks and the
// choice of parameters.
//
// The robot drives `laps` times around a rectangle of perimeter `loop_length_m` at 1 m/s,
// starting in the middle of the bottom edge (that start pose is W = F_1). Fragment frames lie
// at equal arc-length spacing. The scan matcher's alignment of each fragment is the true one
// plus an error drawn from N(0, Sigma) (so the truth is a plausible sample of N(mu_i, Sigma_i)),
// and its M samples are drawn from N(mu_i, Sigma_i) (eq. 7). Exit points follow eq. (4):
// E_i = mu_{i+1}; the last exit E_N is the true pose of the start in F_N. The paper's closure
// (F_1, F_N) hypothesises that E_N lies at the start, up to an error drawn from Sigma_H. With
// several laps, every pair of non-consecutive fragments whose true frames are closer than
// `revisit_radius_m` also gets a closure (anchor: the frame origin). The set's `reference`
// holds the true world frames.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "antslam/slamgraph/fragment_set.hpp"

namespace antslam::slam {

/// Size limits of synthesize(): beyond them a set takes gigabytes to hold and write, and with
/// more than one lap the revisit search over every pair of fragments takes minutes.
inline constexpr std::size_t kMaxSynthFragments = 1'000'000;
inline constexpr std::size_t kMaxSynthSamples = 1'000'000;
inline constexpr std::size_t kMaxRevisitFragments = 20'000;
inline constexpr std::size_t kMaxSynthClosures = 1'000'000;

struct SynthSettings {
  std::size_t fragments = 9;          ///< N
  std::size_t samples = 20;           ///< M samples per alignment (eq. 7)
  double loop_length_m = 53.0;        ///< perimeter of the rectangle, metres
  double aspect = 22.0 / 14.0;        ///< width / height of the rectangle
  std::size_t laps = 1;               ///< times around the loop; > 1 adds revisit closures
  double sigma_xy = 0.10;             ///< alignment standard deviation of x and y, metres
  double sigma_theta = 0.02;          ///< alignment standard deviation of theta, radians
  double correlation = 0.0;           ///< correlation of every pair of (x, y, theta), in (-0.5, 1)
  double closure_sigma_xy = 0.05;     ///< hypothesis standard deviation of x and y, metres
  double closure_sigma_theta = 0.01;  ///< hypothesis standard deviation of theta, radians
  double revisit_radius_m = 1.0;      ///< laps > 1: distance that makes a revisit, metres
  bool noise_free = false;            ///< means and hypotheses equal the truth
  std::size_t trajectory_poses = 10;  ///< robot poses kept per fragment (for maps), count
  std::uint64_t seed = 1;             ///< seeds every random draw
};

/// The paper's three environments (Sec. IV): "paper9" (basement, 53 m loop, 22 m x 14 m),
/// "paper15" (robotics lab, 82 m, 22 m x 24 m), "paper24" (third floor, 137 m, 51 m x 24 m),
/// all with M = 20. Throws std::invalid_argument listing the names.
SynthSettings synth_preset(std::string_view name);

/// Throws std::invalid_argument naming the setting if it is out of range (the limits above; loop
/// length up to 1e6 m, standard deviations up to 1000 m and 10 rad, up to 1000 laps and 10000
/// trajectory poses per fragment).
FragmentSet synthesize(const SynthSettings& settings);

}  // namespace antslam::slam
