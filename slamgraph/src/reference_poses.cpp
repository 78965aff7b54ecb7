#include "slamgraph/g2o.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "slamgraph/trajectory.hpp"

namespace antslam::slam {

namespace {

std::vector<Pose2> read_xytheta(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  std::vector<Pose2> poses;
  std::string text;
  std::size_t line = 0;
  while (std::getline(in, text)) {
    ++line;
    std::istringstream fields(text);
    double v[3];
    std::string rest;
    if (!(fields >> std::ws) || fields.peek() == '#' || fields.eof()) continue;
    if (!(fields >> v[0] >> v[1] >> v[2]) || (fields >> rest))
      throw std::runtime_error(path.string() + ":" + std::to_string(line) +
                               ": expected `x y theta`");
    if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
      throw std::runtime_error(path.string() + ":" + std::to_string(line) + ": non-finite number");
    poses.push_back(Pose2::from_vector({v[0], v[1], v[2]}));
  }
  return poses;
}

}  // namespace

std::vector<Pose2> read_reference_poses(const std::filesystem::path& path) {
  const std::string ext = path.extension().string();
  if (ext == ".g2o") return read_g2o_file(path).vertices;
  if (ext == ".tum") {
    std::vector<Pose2> poses;
    for (const StampedPose& p : read_tum_file(path)) poses.push_back(p.pose);
    return poses;
  }
  return read_xytheta(path);
}

}  // namespace antslam::slam
