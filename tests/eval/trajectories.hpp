#pragma once
// Small trajectories for the evaluation tests.

#include <cmath>
#include <initializer_list>

#include "antslam/slamgraph/trajectory.hpp"

namespace antslam::eval::testing {

struct Row {
  double stamp, x, y, theta;
};

inline slam::Trajectory make_trajectory(std::initializer_list<Row> rows) {
  slam::Trajectory t;
  for (const Row& r : rows) t.push_back({r.stamp, slam::Pose2{r.x, r.y, r.theta}});
  return t;
}

/// A curved, non-degenerate path: n poses one second apart along a widening spiral.
inline slam::Trajectory spiral(std::size_t n) {
  slam::Trajectory t;
  for (std::size_t i = 0; i < n; ++i) {
    const double s = static_cast<double>(i);
    const double r = 1.0 + 0.1 * s, a = 0.3 * s;
    t.push_back(
        {100.0 + s, slam::Pose2{r * std::cos(a), r * std::sin(a), slam::wrap_angle(a + 1.6)}});
  }
  return t;
}

}  // namespace antslam::eval::testing
