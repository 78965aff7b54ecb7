#include "antslam/frontend/fragmenter.hpp"

#include <cmath>
#include <stdexcept>

#include "antslam/aco/random.hpp"
#include "antslam/frontend/pose_covariance.hpp"

namespace antslam::frontend {

namespace {

/// A covariance given in W axes, expressed in the axes of a frame with heading `theta`.
Eigen::Matrix3d in_frame_axes(const Eigen::Matrix3d& covariance, double theta) {
  return compose_covariance(slam::Pose2{0.0, 0.0, -theta}, Eigen::Matrix3d::Zero(), slam::Pose2{},
                            covariance);
}

}  // namespace

void validate(const FragmentationSettings& s) {
  if (!(s.length > 0.0) || !std::isfinite(s.length))
    throw std::invalid_argument("fragmentation: length must be a positive number of metres");
  if (!(s.covariance_scale > 0.0) || !std::isfinite(s.covariance_scale))
    throw std::invalid_argument("fragmentation: covariance_scale must be positive");
  if (s.samples < 1 || s.samples > 100000)
    throw std::invalid_argument("fragmentation: samples must be in [1, 100000]");
}

Fragmenter::Fragmenter(const FragmentationSettings& settings) : settings_(settings) {
  validate(settings_);
}

bool Fragmenter::add(std::size_t scan, double stamp, const slam::Pose2& pose,
                     const Eigen::Matrix3d& covariance) {
  if (!fragments_.empty()) {
    FragmentRecord& f = fragments_.back();
    // The step from the previous scan, with this scan's covariance as the step's (first order).
    const slam::Pose2 previous = f.trajectory.back().pose;
    const slam::Pose2 step = slam::between(last_pose_, pose);
    f.accumulated = compose_covariance(previous, f.accumulated, step,
                                       in_frame_axes(covariance, last_pose_.theta));
    f.last_scan = in_frame_axes(covariance, f.frame.theta);
    f.length += std::hypot(step.x, step.y);
    last_pose_ = pose;
    if (f.length < settings_.length) {
      f.trajectory.push_back({stamp, slam::between(f.frame, pose)});
      ++f.scan_count;
      return false;
    }
  }
  // Eq. (4): the new fragment's frame is the pose where the robot left the previous one.
  FragmentRecord next;
  next.first_scan = scan;
  next.scan_count = 1;
  next.frame = pose;
  next.trajectory.push_back({stamp, slam::Pose2{}});
  fragments_.push_back(std::move(next));
  last_pose_ = pose;
  return true;
}

slam::Pose2 Fragmenter::exit(std::size_t i) const {
  const FragmentRecord& f = fragments_.at(i);
  if (i + 1 < fragments_.size()) return slam::between(f.frame, fragments_[i + 1].frame);
  return f.trajectory.back().pose;
}

Eigen::Matrix3d Fragmenter::exit_covariance(std::size_t i) const {
  const FragmentRecord& f = fragments_.at(i);
  return settings_.covariance_scale *
         (settings_.covariance == AlignmentCovariance::exit_scan ? f.last_scan : f.accumulated);
}

slam::FragmentSet Fragmenter::fragment_set(const std::string& name) const {
  slam::FragmentSet set;
  set.name = name;
  for (std::size_t i = 0; i < fragments_.size(); ++i) {
    slam::Fragment fragment;
    fragment.exit = exit(i);
    fragment.trajectory = fragments_[i].trajectory;
    if (i > 0) {
      // N(mu_i, Sigma_i) over F_i in F_{i-1}, mu_i = E_{i-1}, and eq. (7).
      const slam::Gaussian2 alignment(exit(i - 1), exit_covariance(i - 1));
      aco::Rng rng(aco::mix_seed(settings_.seed, i));
      fragment.samples.reserve(settings_.samples);
      for (std::size_t j = 0; j < settings_.samples; ++j)
        fragment.samples.push_back(alignment.sample(rng));
      fragment.alignment = alignment;
    }
    set.fragments.push_back(std::move(fragment));
  }
  return set;
}

}  // namespace antslam::frontend
