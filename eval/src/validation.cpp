#include "antslam/eval/detail/validation.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace antslam::eval::detail {

void check_max_dt(double max_dt) {
  if (std::isfinite(max_dt) && max_dt >= 0.0) return;
  std::ostringstream message;
  message << "max_dt must be a finite number >= 0 seconds, got " << max_dt;
  throw std::invalid_argument(message.str());
}

void check_sorted(const slam::Trajectory& trajectory, const char* name) {
  const auto later = [](const slam::StampedPose& a, const slam::StampedPose& b) {
    return a.stamp > b.stamp;
  };
  const auto it = std::adjacent_find(trajectory.begin(), trajectory.end(), later);
  if (it == trajectory.end()) return;
  std::ostringstream message;
  message.precision(17);
  message << name << " timestamps decrease after stamp " << it->stamp << " s";
  throw std::invalid_argument(message.str());
}

}  // namespace antslam::eval::detail
