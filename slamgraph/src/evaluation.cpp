#include "slamgraph/evaluation.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "slamgraph/g2o.hpp"
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

TrajectoryError absolute_trajectory_error(std::span<const Pose2> estimate,
                                          std::span<const Pose2> reference) {
  if (estimate.empty() || estimate.size() != reference.size())
    throw std::invalid_argument("trajectory error: " + std::to_string(estimate.size()) +
                                " estimated poses vs " + std::to_string(reference.size()) +
                                " reference poses");
  const auto n = static_cast<double>(estimate.size());
  Eigen::Vector2d ce = Eigen::Vector2d::Zero(), cr = Eigen::Vector2d::Zero();
  for (std::size_t i = 0; i < estimate.size(); ++i) {
    ce += estimate[i].translation();
    cr += reference[i].translation();
  }
  ce /= n;
  cr /= n;
  // Rotation phi minimising sum |R(phi) (e - ce) - (r - cr)|^2.
  double dot = 0.0, cross = 0.0;
  for (std::size_t i = 0; i < estimate.size(); ++i) {
    const Eigen::Vector2d e = estimate[i].translation() - ce, r = reference[i].translation() - cr;
    dot += e.dot(r);
    cross += e.x() * r.y() - e.y() * r.x();
  }
  const double phi = std::atan2(cross, dot);
  const Pose2 rotation{0.0, 0.0, phi};
  TrajectoryError err;
  err.poses = estimate.size();
  double sum_t = 0.0, sum_r = 0.0;
  for (std::size_t i = 0; i < estimate.size(); ++i) {
    const Eigen::Vector2d aligned = rotation * (estimate[i].translation() - ce) + cr;
    const double d = (aligned - reference[i].translation()).norm();
    const double a = wrap_angle(estimate[i].theta + phi - reference[i].theta);
    sum_t += d * d;
    sum_r += a * a;
    err.max_m = std::max(err.max_m, d);
  }
  err.rmse_m = std::sqrt(sum_t / n);
  err.rmse_rad = std::sqrt(sum_r / n);
  return err;
}

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
