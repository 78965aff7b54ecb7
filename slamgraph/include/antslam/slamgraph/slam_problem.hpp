#pragma once
// The AntSLAM problem as a layered-choice problem of the engine (paper Sec. III-B): layer l is
// fragment l + 2 of the paper, its options are the M samples of eq. (7), and the cost of a
// choice is the weight of eq. (10) (summed over every loop closure). It satisfies
// aco::LayeredProblem, so every engine variant runs on it.
//
// The cost is the hot path of the colony (one call per ant), so everything that does not
// depend on the choice is precomputed: each sample's term 1 - N(mu_i, Sigma_i)(s) and its
// cos/sin; each closure's anchor and information matrix. The chain of eq. (8) then needs only
// multiplications and additions (rotations as cos/sin products, angles as plain sums, wrapped
// once per closure), and each closure costs one exp.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "antslam/slamgraph/fragment_set.hpp"

namespace antslam::slam {

class SlamProblem {
 public:
  /// Validates the set (std::invalid_argument naming the problem) and precomputes the terms.
  explicit SlamProblem(const FragmentSet& set);

  std::size_t layer_count() const { return offset_.size() - 1; }
  std::size_t option_count(std::size_t layer) const { return offset_[layer + 1] - offset_[layer]; }

  /// Eq. (10) for one sample per layer (choice[l] < option_count(l)); thread-safe.
  double cost(std::span<const std::uint32_t> choice) const;

  /// A pose during the chain: translation, cos/sin of the angle, and the angle itself as the
  /// unwrapped sum of the chain's angles. No default member initialisers: scratch arrays of
  /// frames stay uninitialised on the hot path.
  struct Frame {
    double x;      ///< metres
    double y;      ///< metres
    double c;      ///< cos(theta)
    double s;      ///< sin(theta)
    double theta;  ///< radians, not wrapped
  };

 private:
  struct Sample {
    Frame pose;    ///< the sample s_{i,j}
    double unary;  ///< 1 - N(mu_i, Sigma_i)(s_{i,j})
  };
  struct Closure {
    std::uint32_t slot;  ///< where F_a is kept while the chain runs on to F_b; unused if a = 0
    bool from_world;     ///< a = 0: F_a = W, nothing to keep
    Frame anchor;        ///< anchor point in F_b
    Pose2 mean;          ///< H
    double info[6];      ///< Omega_H: xx, xy, xt, yy, yt, tt
  };
  /// The closures that start (keep F_i) and end (evaluate) at fragment i.
  struct Event {
    std::size_t fragment;
    std::vector<std::uint32_t> opening, closing;
  };

  double closure_term(const Closure& c, const Frame& from, const Frame& to) const;
  double chain_cost(std::span<const std::uint32_t> choice, Frame* opened) const;

  std::vector<std::size_t> offset_;  ///< samples_ index of layer l's first option
  std::vector<Sample> samples_;
  std::vector<Closure> closures_;
  std::vector<Event> events_;    ///< by increasing fragment
  std::size_t kept_frames_ = 0;  ///< closures with a > 0
};

}  // namespace antslam::slam
