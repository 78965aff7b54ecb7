#include "antslam/frontend/odometry_noise.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "antslam/slamgraph/gaussian2.hpp"

namespace antslam::frontend {

void validate(const OdometryNoise& noise) {
  const auto check = [](double value, const char* field) {
    if (!(value >= 0.0 && std::isfinite(value)))
      throw std::invalid_argument(std::string("odometry noise: ") + field +
                                  " must be a finite number >= 0");
  };
  check(noise.linear, "linear");
  check(noise.angular, "angular");
  check(noise.drift, "drift");
  if (!std::isfinite(noise.heading_bias))
    throw std::invalid_argument("odometry noise: heading_bias must be finite");
}

std::vector<slam::Pose2> noisy_odometry(std::span<const slam::Pose2> path,
                                        const OdometryNoise& noise, aco::Rng& rng) {
  validate(noise);
  std::vector<slam::Pose2> odometry;
  odometry.reserve(path.size());
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (i == 0) {
      odometry.push_back(path[0]);
      continue;
    }
    const slam::Pose2 u = slam::between(path[i - 1], path[i]);
    const double distance = std::hypot(u.x, u.y);
    const double linear = noise.linear * distance;
    const double angular = noise.angular * std::abs(u.theta) + noise.drift * distance;
    const slam::Pose2 noisy{
        u.x + linear * slam::standard_normal(rng), u.y + 0.5 * linear * slam::standard_normal(rng),
        u.theta + angular * slam::standard_normal(rng) + noise.heading_bias * distance};
    odometry.push_back(odometry.back() * noisy);
  }
  return odometry;
}

}  // namespace antslam::frontend
