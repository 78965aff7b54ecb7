#pragma once
// How well the frontend knows where one fragment lies relative to another: fragments are nodes,
// alignments (F_{i+1} in F_i) and accepted loop closures are edges with a relative pose and its
// covariance. The estimate between two fragments follows the path of least uncertainty
// (Dijkstra on the trace of the propagated covariance), so after a loop is closed the places
// near its two ends are close again, and the next closure search uses a small, re-centred
// window.

#include <Eigen/Core>
#include <cstddef>
#include <span>
#include <vector>

#include "antslam/slamgraph/pose2.hpp"

namespace antslam::frontend {

struct GraphEdge {
  std::size_t from = 0;        ///< node whose frame the pose is given in
  std::size_t to = 0;          ///< node whose frame is located
  slam::Pose2 relative;        ///< F_to in F_from
  Eigen::Matrix3d covariance;  ///< of `relative` (F_from axes)
};

struct RelativeEstimate {
  bool reachable = false;                                ///< a path to the target exists
  slam::Pose2 pose;                                      ///< F_target in F_node
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  ///< of `pose` (F_node axes)
};

/// For each node 0..nodes-1: the pose of `target`'s frame in that node's frame, composed along
/// the path whose propagated covariance has the smallest translational trace.
std::vector<RelativeEstimate> relative_to(std::size_t target, std::size_t nodes,
                                          std::span<const GraphEdge> edges);

}  // namespace antslam::frontend
