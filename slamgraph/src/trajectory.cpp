#include "antslam/slamgraph/trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "text_lines.hpp"

namespace antslam::slam {

using detail::parse_number;

namespace {

/// Why a pose cannot be in a TUM file, or empty: what the reader refuses, the writer never
/// writes.
std::string pose_problem(double stamp, double x, double y, double z) {
  if (!std::isfinite(stamp) || !std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
    return "non-finite number";
  std::ostringstream problem;
  if (std::abs(stamp) > kMaxTimestamp)
    problem << "timestamp " << stamp << " s is beyond " << kMaxTimestamp << " s";
  else if (std::max({std::abs(x), std::abs(y), std::abs(z)}) > kMaxCoordinate)
    problem << "position (" << x << ", " << y << ", " << z << ") m is beyond " << kMaxCoordinate
            << " m";
  return problem.str();
}

/// A quaternion |q| may miss 1 by this much (rounding in the file) and is normalised; further
/// off it is not a rotation someone meant.
constexpr double kQuaternionNormTolerance = 0.01;

}  // namespace

Trajectory read_tum(std::istream& in, const std::string& source) {
  Trajectory trajectory;
  detail::for_each_data_line(in, source, [&](std::istringstream& fields, std::size_t line) {
    const auto fail = [&](const std::string& problem) { detail::fail_at(source, line, problem); };
    double v[8];
    std::string token;
    for (double& x : v) {
      if (!(fields >> token)) fail("expected 8 numbers `timestamp x y z qx qy qz qw`");
      if (!parse_number(token, x)) fail("'" + token + "' is not a number");
    }
    if (fields >> token) fail("unexpected extra field '" + token + "'");
    const std::string problem = pose_problem(v[0], v[1], v[2], v[3]);
    if (!problem.empty()) fail(problem);
    const double qx = v[4], qy = v[5], qz = v[6], qw = v[7];
    if (!std::isfinite(qx) || !std::isfinite(qy) || !std::isfinite(qz) || !std::isfinite(qw))
      fail("non-finite number");
    const double norm = std::sqrt(qx * qx + qy * qy + qz * qz + qw * qw);
    if (!(std::abs(norm - 1.0) <= kQuaternionNormTolerance)) {
      std::ostringstream message;
      message << "quaternion (" << qx << ", " << qy << ", " << qz << ", " << qw << ") has norm "
              << norm << ", not 1 (a rotation's quaternion is a unit quaternion)";
      fail(message.str());
    }
    if (!trajectory.empty() && v[0] < trajectory.back().stamp) fail("timestamp decreases");
    // Yaw of the rotation q v q* / |q|^2: the same for q and any multiple of it.
    const double yaw = std::atan2(2.0 * (qw * qz + qx * qy), qw * qw + qx * qx - qy * qy - qz * qz);
    trajectory.push_back({v[0], Pose2{v[1], v[2], wrap_angle(yaw)}});
  });
  return trajectory;
}

Trajectory read_tum_file(const std::filesystem::path& path) {
  std::ifstream in = detail::open_input(path);
  return read_tum(in, path.string());
}

void write_tum(std::ostream& out, const Trajectory& trajectory) {
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    const StampedPose& p = trajectory[i];
    const std::string problem = pose_problem(p.stamp, p.pose.x, p.pose.y, 0.0);
    if (!problem.empty() || !std::isfinite(p.pose.theta))
      throw std::invalid_argument("TUM trajectory: pose " + std::to_string(i) + ": " +
                                  (problem.empty() ? "non-finite heading" : problem));
    if (i > 0 && p.stamp < trajectory[i - 1].stamp)
      throw std::invalid_argument("TUM trajectory: timestamps decrease at pose " +
                                  std::to_string(i) + " (TUM files need them in time order)");
  }
  out << "# timestamp x y z qx qy qz qw\n";
  for (const StampedPose& p : trajectory) {
    out << std::fixed << std::setprecision(6) << p.stamp << ' ' << std::setprecision(9) << p.pose.x
        << ' ' << p.pose.y << " 0 0 0 " << std::sin(p.pose.theta / 2.0) << ' '
        << std::cos(p.pose.theta / 2.0) << '\n';
  }
}

double path_length(const Trajectory& trajectory) {
  double length = 0.0;
  for (std::size_t i = 1; i < trajectory.size(); ++i)
    length += (trajectory[i].pose.translation() - trajectory[i - 1].pose.translation()).norm();
  return length;
}

}  // namespace antslam::slam
