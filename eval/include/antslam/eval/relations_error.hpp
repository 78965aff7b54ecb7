#pragma once
// The relations metric of Kuemmerle et al. 2009, eq. (1): for every relation (t1, t2, delta*)
// whose two stamps both match a pose of the estimate (nearest stamp within max_dt), the error of
// the estimated motion delta = x_t1^-1 x_t2 against delta* (relative_error.hpp). Reported, as in
// their tables, as mean +- standard deviation of the absolute and of the squared translational
// (m, m^2) and rotational (deg, deg^2) errors. Relations that cannot be matched are skipped and
// counted.
//
// The translational error |t(delta) - t(delta*)| does not depend on which side of delta* the
// difference is taken; Cartographer's compute_relations_metrics uses |t(delta delta*^-1)|, which
// does (its own TODO says so) and differs slightly when the relative rotation is large.

#include <cstddef>
#include <span>

#include "antslam/eval/relations.hpp"
#include "antslam/eval/statistics.hpp"
#include "antslam/slamgraph/trajectory.hpp"

namespace antslam::eval {

struct RelationsResult {
  std::size_t used = 0;            ///< relations scored
  std::size_t skipped = 0;         ///< relations with a stamp missing from the estimate
  MeanStd translation_m;           ///< |t(E)|, metres
  MeanStd translation_squared_m2;  ///< |t(E)|^2, square metres
  MeanStd rotation_deg;            ///< |theta(E)|, degrees
  MeanStd rotation_squared_deg2;   ///< |theta(E)|^2, square degrees
};

/// Throws std::invalid_argument if max_dt is negative or not finite, if the estimate's
/// timestamps decrease, or if no relation can be scored.
RelationsResult relations_error(const slam::Trajectory& estimate,
                                std::span<const Relation> relations, double max_dt);

}  // namespace antslam::eval
