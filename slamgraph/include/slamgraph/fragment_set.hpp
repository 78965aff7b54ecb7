#pragma once
// The fragment set (paper Sec. III-A): N map fragments, each with a local frame F_i and exit
// point E_i; for every fragment after the first, a Gaussian over its alignment to the previous
// one and M samples from it (eq. 7); one or more loop closures with hypothesis H and Gaussian
// N(mu_H, Sigma_H). Indices are 0-based: the paper's fragment i is fragments[i - 1].
//
// Reading of eq. (10) used throughout: the alignment term of fragment i is the value of
// N(mu_i, Sigma_i) at the chosen sample (the sample takes the place of E_{i-1} as the origin of
// F_i); the closure term is the value of N(mu_H, Sigma_H) at the pose, in F_a, of the closure's
// anchor point of F_b as the chain of eq. (8) places it. For the paper's single loop, a = 0
// (F_1 = W), b = N - 1 and the anchor is E_N, so that pose is W T_{E_N} of eq. (8).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "slamgraph/gaussian2.hpp"
#include "slamgraph/pose2.hpp"
#include "slamgraph/trajectory.hpp"

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

  std::size_t layer_count() const { return fragments.empty() ? 0 : fragments.size() - 1; }
};

/// Throws std::invalid_argument with a one-line message naming the problem (e.g.
/// "fragments[3].samples is empty") if the set is not usable: fewer than 2 fragments, a missing
/// alignment or samples after the first fragment, non-finite numbers, no closure, or a closure
/// with from >= to or an index out of range.
void validate(const FragmentSet& set);

/// Eq. (8): world poses of every fragment frame F_1..F_N (F_1 = W) for a choice of one sample
/// per fragment 2..N (choice.size() == N - 1).
std::vector<Pose2> world_frames(const FragmentSet& set, std::span<const std::uint32_t> choice);

/// Pose of closure c's anchor in F_a for the given world frames.
Pose2 closure_pose(const LoopClosure& c, std::span<const Pose2> frames);

/// Eq. (10), summed over all closures: sum_i (1 - N(mu_i, Sigma_i)(s_i)) + sum_H (1 - N_H(.)).
/// Straightforward reference implementation; the ACO adapter has a faster equivalent.
double path_weight(const FragmentSet& set, std::span<const std::uint32_t> choice);

}  // namespace antslam::slam
