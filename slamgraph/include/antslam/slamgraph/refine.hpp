#pragma once
// NLopt local refinement: continuous optimisation of the alignments X_2..X_N,
// minimising the same eq. (10) weight as the ants (AlignmentObjective, analytic gradient),
// starting from a discrete ACO result or any other alignments.
//
// Bounds: each alignment stays within the bounding box of its samples and its mean, widened
// by `bound_sigmas` standard deviations of its Gaussian per coordinate (angles as offsets from
// the mean, so the box never straddles the +-pi cut). A start outside the box widens the box
// to include it. The result is never worse than the start: the best point NLopt evaluated is
// returned, and the start itself is evaluated first.
//
// Graduated non-convexity (Blake and Zisserman 1987; Yang et al. 2020). A term of eq. (10) is
// flat far from its mean: a loop closure the start misses by many standard deviations has no
// gradient, so a local search from there never closes the loop (real logs: closures 80-260
// sigma off after 370 m of scan matching). With `graduated`, the refinement also minimises the
// widened weight sum s^2 (1 - exp(-m / (2 s^2))) (alignment_objective.hpp) for s = s_0,
// s_0 / f, ..., 1, each stage starting where the last ended: at s_0 = sqrt(chi2 of the start)
// every term is inside its convex region (it is least squares up to the factor 1/2), and the
// last stage is eq. (10) itself. Of the plain and the graduated result the one with the lower
// eq. (10) weight is returned.

#include <cstdint>
#include <span>
#include <stop_token>
#include <string_view>
#include <vector>

#include "antslam/slamgraph/alignment_objective.hpp"
#include "antslam/slamgraph/fragment_set.hpp"

namespace antslam::slam {

enum class RefineAlgorithm {
  lbfgs,   ///< NLopt LD_LBFGS, gradient-based, bound-constrained (default)
  slsqp,   ///< NLopt LD_SLSQP, gradient-based sequential quadratic programming
  bobyqa,  ///< NLopt LN_BOBYQA, derivative-free (quadratic models in the box)
};

std::string_view to_string(RefineAlgorithm a);
/// Throws std::invalid_argument listing the valid names.
RefineAlgorithm parse_refine_algorithm(std::string_view name);

struct RefineSettings {
  RefineAlgorithm algorithm = RefineAlgorithm::lbfgs;  ///< NLopt algorithm
  double bound_sigmas = 3.0;          ///< box widening beyond the samples, in standard deviations
  int max_evaluations = 2000;         ///< objective evaluations per refinement (count)
  double relative_tolerance = 1e-10;  ///< stop when the weight changes by less (fraction)
  double time_limit_s = 0.0;          ///< wall-clock budget per refinement in seconds; 0 = none
  int lbfgs_memory = 10;  ///< L-BFGS stored correction pairs (count); NLopt's own default grows
                          ///< to about 1.3e6 / n pairs, which is slow on large graphs
  bool graduated = true;  ///< also refine by graduated non-convexity (above); max_evaluations
                          ///< then applies to every stage
  double graduation_factor = 2.0;  ///< kernel width divided by this per stage (> 1)
  std::stop_token stop{};  ///< once stop is requested, the refinement ends at its next evaluation
                           ///< with the best point so far (optimize() sets it from its own)
};

/// Throws std::invalid_argument naming the first nonsensical field.
void validate(const RefineSettings& settings);

struct RefineResult {
  std::vector<Pose2> alignments;  ///< refined X_2..X_N
  Scores start;                   ///< objectives at the start
  Scores scores;                  ///< objectives at the result; weight <= start.weight
  int evaluations = 0;            ///< objective evaluations used
  bool graduated = false;         ///< the graduated refinement gave the result
};

/// Holds the objective and the bounds of one fragment set; refine() may be called many times.
/// Not thread-safe; use one Refiner per thread.
class Refiner {
 public:
  /// Validates the set and the settings (std::invalid_argument naming the problem).
  Refiner(const FragmentSet& set, const RefineSettings& settings);

  RefineResult refine(std::span<const Pose2> start);
  /// The same within `seconds` of wall-clock time (0 = no limit) instead of
  /// settings.time_limit_s: NLopt stops at the first evaluation past it, and no graduated stage
  /// starts after it. A caller with an overall budget passes what is left of it.
  RefineResult refine(std::span<const Pose2> start, double seconds);

  /// The box of alignment i (0-based layer), as packed vectors (x, y, theta).
  std::span<const double> lower() const { return lower_; }
  std::span<const double> upper() const { return upper_; }

 private:
  AlignmentObjective objective_;
  RefineSettings settings_;
  std::vector<double> mean_angle_;  // mu_theta per alignment, to unwrap starts near it
  std::vector<double> lower_, upper_;
};

}  // namespace antslam::slam
