#include "slamgraph/trajectory.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace antslam::slam {

namespace {

[[noreturn]] void fail(const std::string& source, std::size_t line, const std::string& problem) {
  throw std::runtime_error(source + ":" + std::to_string(line) + ": " + problem);
}

/// Whole-token number, accepting nan/inf so that they can be reported as non-finite.
bool parse_number(const std::string& token, double& value) {
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  return ec == std::errc() && ptr == end;
}

}  // namespace

Trajectory read_tum(std::istream& in, const std::string& source) {
  Trajectory trajectory;
  std::string text;
  std::size_t line = 0;
  while (std::getline(in, text)) {
    ++line;
    const auto first = text.find_first_not_of(" \t\r");
    if (first == std::string::npos || text[first] == '#') continue;
    std::istringstream fields(text);
    double v[8];
    std::string token;
    for (double& x : v) {
      if (!(fields >> token) || !parse_number(token, x))
        fail(source, line, "expected 8 numbers `timestamp x y z qx qy qz qw`");
    }
    if (fields >> token) fail(source, line, "unexpected extra field '" + token + "'");
    for (double x : v)
      if (!std::isfinite(x)) fail(source, line, "non-finite number");
    const double qx = v[4], qy = v[5], qz = v[6], qw = v[7];
    if (qx * qx + qy * qy + qz * qz + qw * qw < 1e-12) fail(source, line, "zero quaternion");
    if (!trajectory.empty() && v[0] < trajectory.back().stamp)
      fail(source, line, "timestamp decreases");
    const double yaw = std::atan2(2.0 * (qw * qz + qx * qy), 1.0 - 2.0 * (qy * qy + qz * qz));
    trajectory.push_back({v[0], Pose2{v[1], v[2], wrap_angle(yaw)}});
  }
  if (in.bad()) throw std::runtime_error(source + ": read error");
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

}  // namespace antslam::slam
