#pragma once
// The error of an estimated relative motion against a reference one, shared by the relative pose
// error (Sturm et al. 2012) and the relations metric (Kuemmerle et al. 2009, eq. 1):
//   delta = a^-1 b (estimated motion from pose a to pose b, in a's frame),
//   E = delta* (-) delta = delta*^-1 delta,
// translational error |t(E)| = |t(delta) - t(delta*)| (m), rotational error |theta(E)| =
// |wrap(theta(delta) - theta(delta*))| (rad).

#include <cmath>
#include <numbers>

#include "antslam/slamgraph/pose2.hpp"

namespace antslam::eval {

struct RelativeError {
  double translation = 0.0;  ///< metres, >= 0
  double rotation = 0.0;     ///< radians, in [0, pi]
};

/// Error of the estimated motion from `from` to `to` against `reference_motion`.
inline RelativeError relative_error(const slam::Pose2& from, const slam::Pose2& to,
                                    const slam::Pose2& reference_motion) {
  const slam::Pose2 error = reference_motion.inverse() * slam::between(from, to);
  return {error.translation().norm(), std::abs(error.theta)};
}

/// Radians to degrees, for reported rotational errors.
inline double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

}  // namespace antslam::eval
