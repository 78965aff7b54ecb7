#pragma once
// Argument checks shared by the evaluation functions; each throws std::invalid_argument.

#include "antslam/slamgraph/trajectory.hpp"

namespace antslam::eval::detail {

/// max_dt must be finite and >= 0 (seconds).
void check_max_dt(double max_dt);

/// Timestamps must not decrease; `name` ("estimate", "reference") goes into the message.
void check_sorted(const slam::Trajectory& trajectory, const char* name);

}  // namespace antslam::eval::detail
