#pragma once
// Fragmentation (paper Sec. III-A): the scan-matcher trajectory is cut into fragments whenever
// the robot has travelled `length` metres since the fragment began. Fragment i has the frame
// F_i (the pose of its first scan), the exit E_i (the pose where the robot left it, which is
// F_{i+1}: eq. (4)), and, from the second fragment on, the Gaussian N(mu_i, Sigma_i) over F_i in
// F_{i-1} with mu_i = E_{i-1}, and M samples drawn from it (eq. (7)).

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "antslam/slamgraph/fragment_set.hpp"
#include "antslam/slamgraph/pose2.hpp"
#include "antslam/slamgraph/trajectory.hpp"

namespace antslam::frontend {

/// Which covariance the alignment Gaussian of a fragment gets.
enum class AlignmentCovariance {
  exit_scan,    ///< the paper, literally: eqs. (5)-(6) of the scan that leaves the fragment
  accumulated,  ///< eqs. (5)-(6) of every scan of the fragment, composed along the fragment as
                ///< independent steps (first order): the drift the alignment must absorb
};

struct FragmentationSettings {
  double length = 5.0;       ///< metres travelled per fragment (paper Sec. IV: more than 5 m)
  std::size_t samples = 20;  ///< M, samples per alignment (eq. (7); paper Sec. IV: 20)
  std::uint64_t seed = 1;    ///< seeds the samples: fragment i draws from stream (seed, i)
  AlignmentCovariance covariance = AlignmentCovariance::accumulated;  ///< see the enum
  double covariance_scale = 8.0;  ///< multiplies the alignment covariance: 1 keeps the scan
                                  ///< matcher's model (honest on simulated scans); 8 makes the
                                  ///< accumulated one honest on real logs (docs/frontend.md)
};

/// Throws std::invalid_argument naming the first nonsensical field.
void validate(const FragmentationSettings& settings);

/// One fragment as the frontend builds it.
struct FragmentRecord {
  std::size_t first_scan = 0;   ///< index of the scan at the origin of F_i
  std::size_t scan_count = 0;   ///< scans in the fragment (first_scan onwards)
  slam::Pose2 frame;            ///< F_i in the scan matcher's world frame W
  slam::Trajectory trajectory;  ///< robot poses of its scans, in F_i
  double length = 0.0;          ///< metres travelled inside the fragment
  Eigen::Matrix3d accumulated = Eigen::Matrix3d::Zero();  ///< covariance of the last pose in F_i
                                                          ///< (composed, see the enum)
  Eigen::Matrix3d last_scan = Eigen::Matrix3d::Zero();    ///< eqs. (5)-(6) of the last scan, in
                                                          ///< F_i axes
};

class Fragmenter {
 public:
  explicit Fragmenter(const FragmentationSettings& settings);

  /// Adds the next scan: its index, time, robot pose in W and the covariance of eqs. (5)-(6)
  /// (W axes). Returns true if the scan starts a new fragment (the first scan does).
  bool add(std::size_t scan, double stamp, const slam::Pose2& pose,
           const Eigen::Matrix3d& covariance);

  const std::vector<FragmentRecord>& fragments() const { return fragments_; }

  /// The exit E_i of fragment i in F_i: the first pose of fragment i + 1, or the last pose of
  /// the last fragment.
  slam::Pose2 exit(std::size_t i) const;

  /// The covariance of the alignment of fragment i + 1 to fragment i (F_i axes), as chosen by
  /// the settings (mode and scale).
  Eigen::Matrix3d exit_covariance(std::size_t i) const;

  /// The fragment set of eq. (13) without closures: exits, alignments N(E_{i-1}, Sigma_i),
  /// M samples each (eq. (7)) and the trajectories.
  slam::FragmentSet fragment_set(const std::string& name) const;

  const FragmentationSettings& settings() const { return settings_; }

 private:
  FragmentationSettings settings_;
  std::vector<FragmentRecord> fragments_;
  slam::Pose2 last_pose_;
  Eigen::Matrix3d next_start_ = Eigen::Matrix3d::Zero();  ///< the cut scan's own covariance
};

}  // namespace antslam::frontend
