#pragma once
// The fragment set (paper Sec. III-A): N map fragments, each with a local frame F_i and exit
// point E_i; for every fragment after the first, a Gaussian over its alignment to the previous
// one and M samples from it (eq. 7); one or more loop closures with hypothesis H and Gaussian
// N(mu_H, Sigma_H). Indices are 0-based: the paper's fragment i is fragments[i - 1].
//
// An "alignment" X_i is the pose of F_i in F_{i-1} (i >= 1): a sample s_{i,j} when an ant picks
// one, any pose when the alignments are optimised continuously (NLopt, Ceres). The chain of
// eq. (8) places F_i at X_1 * ... * X_i in the world frame W = F_1.
//
// Reading of eq. (10) used throughout: the alignment term of fragment i is the value of
// N(mu_i, Sigma_i) at X_i (the chosen sample takes the place of E_{i-1} as the origin of F_i);
// the closure term is the value of N(mu_H, Sigma_H) at the pose, in F_a, of the closure's
// anchor point of F_b as the chain of eq. (8) places it. For the paper's single loop, a = 0
// (F_1 = W), b = N - 1 and the anchor is E_N, so that pose is W T_{E_N} of eq. (8). With several
// closures the weight sums all closure terms (the paper's future-work option of ants traversing
// every loop within one tour). Values are peak-normalised (gaussian2.hpp), so every term of the
// weight lies in [0, 1] and a perfect map weighs 0.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "antslam/slamgraph/gaussian2.hpp"
#include "antslam/slamgraph/pose2.hpp"
#include "antslam/slamgraph/trajectory.hpp"

namespace antslam::slam {

struct Fragment {
  Pose2 exit;                          ///< E_i, in F_i
  std::optional<Gaussian2> alignment;  ///< N(mu_i, Sigma_i) over F_i in F_{i-1}; none for F_1
  std::vector<Pose2> samples;          ///< S_i (eq. 7): candidate poses of F_i in F_{i-1}
  Trajectory trajectory;               ///< optional robot poses while in this fragment, in F_i
};

struct LoopClosure {
  std::size_t from = 0;  ///< fragment a (the earlier one)
  std::size_t to = 0;    ///< fragment b (the later one), b > a
  Pose2 anchor;          ///< the point of F_b whose pose in F_a is hypothesised (E_N in the paper)
  Gaussian2 hypothesis;  ///< N(mu_H, Sigma_H) over the anchor's pose in F_a; its mean is H
};

struct FragmentSet {
  std::string name;                   ///< free text (source log, generator settings)
  std::vector<Fragment> fragments;    ///< N >= 2 fragments
  std::vector<LoopClosure> closures;  ///< at least one
  std::vector<Pose2> reference;       ///< optional ground-truth world poses of F_1..F_N, or empty

  std::size_t layer_count() const { return fragments.empty() ? 0 : fragments.size() - 1; }
};

/// The variances (diagonal of a covariance, m^2 or rad^2) and information entries (diagonal of
/// its inverse) a set may hold at most: beyond, a Mahalanobis distance through them could
/// overflow (eq. 10 would read inf) or lose every digit. A standard deviation of 1e9 m or 1e-9 m
/// is already far outside any sensor's.
inline constexpr double kMaxVariance = 1e18;
inline constexpr double kMaxInformation = 1e18;

/// Throws std::invalid_argument with a one-line message naming the problem (e.g.
/// "fragments[3].samples is empty") if the set is not usable: fewer than 2 fragments, a missing
/// alignment or samples after the first fragment, non-finite numbers, positions beyond
/// kMaxCoordinate, timestamps beyond kMaxTimestamp, a covariance beyond the limits above, no
/// closure, a closure with from >= to or an index out of range, or a reference of the wrong size.
void validate(const FragmentSet& set);

/// The alignments X_1..X_{N-1} that a choice of one sample per fragment 2..N selects.
std::vector<Pose2> chosen_alignments(const FragmentSet& set, std::span<const std::uint32_t> choice);

/// The means mu_2..mu_N: the scan matcher's own alignments (the uncorrected map).
std::vector<Pose2> mean_alignments(const FragmentSet& set);

/// Eq. (8) for any alignments: world poses of F_1..F_N, F_1 = W.
std::vector<Pose2> chain(std::span<const Pose2> alignments);

/// The alignments X_i = F_{i-1}^-1 F_i of world frames (inverse of chain()).
std::vector<Pose2> relative_alignments(std::span<const Pose2> frames);

/// Eq. (8): world poses of every fragment frame for a choice of one sample per fragment 2..N
/// (choice.size() == N - 1).
std::vector<Pose2> world_frames(const FragmentSet& set, std::span<const std::uint32_t> choice);

/// Pose of closure c's anchor in F_a for the given world frames.
Pose2 closure_pose(const LoopClosure& c, std::span<const Pose2> frames);

/// The two objectives every method is scored on.
struct Scores {
  double weight = 0.0;  ///< eq. (10) summed over all closures; each term in [0, 1]
  double chi2 = 0.0;    ///< least squares: sum of squared Mahalanobis distances r^T Omega r
};

/// Both objectives for continuous alignments (alignments.size() == N - 1). Straightforward
/// reference implementation; SlamProblem and AlignmentObjective are the fast equivalents.
Scores score(const FragmentSet& set, std::span<const Pose2> alignments);

/// Eq. (10), summed over all closures: sum_i (1 - N(mu_i, Sigma_i)(s_i)) + sum_H (1 - N_H(.)).
double path_weight(const FragmentSet& set, std::span<const std::uint32_t> choice);

/// The robot trajectory in W for the given world frames: every fragment's trajectory moved by
/// its frame, in fragment order; a fragment without trajectory contributes its frame with the
/// fragment index as time stamp.
Trajectory world_trajectory(const FragmentSet& set, std::span<const Pose2> frames);

}  // namespace antslam::slam
