#pragma once
// A pose graph read as an odometry chain with loop closures: every edge between consecutive
// vertices i and i+1 (either direction) is odometry, and the first one of each pair is the
// chain's step from i to i+1; every other edge is a loop closure. Both a g2o pose graph and a
// fragment set (pose_graph_of: alignments as the chain, its loop closures as closures) read so.

#include <cstddef>
#include <string>
#include <vector>

#include "antslam/slamgraph/g2o.hpp"

namespace antslam::slam {

struct ChainSplit {
  std::vector<std::size_t> chain;     ///< chain[i]: index in graph.edges of the step i -> i+1
  std::vector<std::size_t> closures;  ///< indices in graph.edges of the loop closures, in order
};

/// Whether an edge joins consecutive vertices (odometry, always kept by the robust back ends).
inline bool is_odometry(const PoseGraphEdge& e) { return e.from + 1 == e.to || e.to + 1 == e.from; }

/// Throws std::runtime_error "source: no edge between vertices i and i+1 (...)" when the chain
/// is broken, and "source: ..." for a graph of fewer than 2 vertices.
ChainSplit split_chain(const PoseGraph& graph, const std::string& source);

/// World poses of the vertices by composing the chain's steps from the identity at vertex 0.
std::vector<Pose2> chain_poses(const PoseGraph& graph, const ChainSplit& split);

}  // namespace antslam::slam
