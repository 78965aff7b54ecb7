#include "slamgraph/trajectory.hpp"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "text_lines.hpp"

namespace antslam::slam {

using detail::parse_number;

Trajectory read_tum(std::istream& in, const std::string& source) {
  Trajectory trajectory;
  detail::for_each_data_line(in, source, [&](std::istringstream& fields, std::size_t line) {
    const auto fail = [&](const std::string& problem) { detail::fail_at(source, line, problem); };
    double v[8];
    std::string token;
    for (double& x : v) {
      if (!(fields >> token) || !parse_number(token, x))
        fail("expected 8 numbers `timestamp x y z qx qy qz qw`");
    }
    if (fields >> token) fail("unexpected extra field '" + token + "'");
    for (double x : v)
      if (!std::isfinite(x)) fail("non-finite number");
    const double qx = v[4], qy = v[5], qz = v[6], qw = v[7];
    if (qx * qx + qy * qy + qz * qz + qw * qw < 1e-12) fail("zero quaternion");
    if (!trajectory.empty() && v[0] < trajectory.back().stamp) fail("timestamp decreases");
    const double yaw = std::atan2(2.0 * (qw * qz + qx * qy), 1.0 - 2.0 * (qy * qy + qz * qz));
    trajectory.push_back({v[0], Pose2{v[1], v[2], wrap_angle(yaw)}});
  });
  return trajectory;
}

Trajectory read_tum_file(const std::filesystem::path& path) {
  if (std::filesystem::is_directory(path))
    throw std::runtime_error(path.string() + ": is a directory, expected a TUM file");
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  return read_tum(in, path.string());
}

void write_tum(std::ostream& out, const Trajectory& trajectory) {
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
