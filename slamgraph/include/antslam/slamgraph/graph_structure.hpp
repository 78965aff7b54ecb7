#pragma once
// What the optimizers need to know about a pose graph (g2o.hpp) beyond its edges: which vertices
// stay fixed, initial poses where the file gives none, whether every vertex is tied to a fixed
// one, and both objectives at given vertex poses.
//
// Each edge is seen from its lower vertex: an edge (i, j, z) with i < j as stored, one with
// i > j inverted to first order (g2o.hpp's oriented(): z^-1 with covariance J Sigma J^T), as the
// fragment chain sees it. Its residual at vertex poses X is r = X_lo^-1 X_hi - mu as a vector
// (x, y, theta), the angle wrapped. Least squares is much better behaved so: on mit.g2o, whose
// loop closures are all stored from the later vertex, Levenberg-Marquardt from the file's poses
// stops in a local minimum at chi2 6694 with the stored direction and reaches 768.5 with this
// one (the stored direction's own minimum next to it: 769.7). Each edge is one term of both
// objectives, as each alignment and closure is for a fragment set: the eq. (10) weight sums
// 1 - exp(-r^T Omega r / 2), the least-squares cost chi2 sums r^T Omega r.

#include <Eigen/Core>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "antslam/slamgraph/fragment_set.hpp"
#include "antslam/slamgraph/g2o.hpp"

namespace antslam::slam {

/// The vertices the optimizers hold constant: the graph's FIX vertices, or vertex 0.
std::vector<std::size_t> fixed_vertices(const PoseGraph& graph);

/// Poses that compose the edges along a spanning tree from vertex 0 (at the origin): a breadth
/// first search that takes odometry edges (between consecutive ids) before any other, so that
/// every vertex an odometry chain reaches gets the chain's pose, and each further session is
/// entered through one of the edges that join it to the vertices placed so far. Throws
/// std::runtime_error "source: vertex k is joined to vertex 0 by no chain of edges".
std::vector<Pose2> spanning_tree_poses(const PoseGraph& graph, const std::string& source);

/// Throws std::invalid_argument "source: vertex k is joined to no fixed vertex by edges ..."
/// unless every vertex is connected to a fixed one (otherwise its pose is undetermined).
void check_anchored(const PoseGraph& graph, const std::string& source);

/// An edge seen from its lower vertex (above).
struct OrientedEdge {
  std::size_t lo = 0;           ///< the lower vertex
  std::size_t hi = 0;           ///< the higher vertex
  Pose2 mean;                   ///< pose of hi in lo's frame
  Eigen::Matrix3d information;  ///< of that pose
};

/// Every edge of the graph, oriented, in file order.
std::vector<OrientedEdge> oriented_edges(const PoseGraph& graph);

/// r = X_lo^-1 X_hi - mean of one edge (above).
Eigen::Vector3d edge_residual(const OrientedEdge& edge, const Pose2& lo, const Pose2& hi);

/// Both objectives over every edge at the vertex poses (poses.size() == vertex count).
Scores score(const PoseGraph& graph, std::span<const Pose2> poses);

}  // namespace antslam::slam
