#pragma once
// Absolute trajectory error (Sturm et al. 2012): after the estimate is moved by a rigid transform
// T (align() or the identity), the error of pose i is F_i = r_i^-1 (T e_i);
//   translational error |t(F_i)| = |T e_i - r_i| (m), rotational error |theta(F_i)| (deg);
// ATE RMSE = sqrt(sum_i |t(F_i)|^2 / n), the figure of the laser SLAM evaluation paper, Table I.

#include <span>

#include "antslam/eval/association.hpp"
#include "antslam/eval/statistics.hpp"
#include "antslam/slamgraph/pose2.hpp"

namespace antslam::eval {

struct AteResult {
  slam::Pose2 alignment;          ///< transform T applied to the estimate (metres, radians)
  ErrorStatistics translation_m;  ///< position errors, metres
  ErrorStatistics rotation_deg;   ///< heading errors, degrees
};

/// ATE of `alignment * estimate` against the reference over the associated pairs. Pass
/// align(pairs) for the usual aligned ATE, the identity (default) for the raw error.
/// Throws std::invalid_argument if `pairs` is empty.
AteResult ate(std::span<const PosePair> pairs, const slam::Pose2& alignment = {});

/// The aligned ATE of two pose lists matched by index (e.g. the vertices of a pose graph and its
/// reference poses). Throws std::invalid_argument if they differ in length or are empty.
AteResult indexed_ate(std::span<const slam::Pose2> estimate,
                      std::span<const slam::Pose2> reference);

}  // namespace antslam::eval
