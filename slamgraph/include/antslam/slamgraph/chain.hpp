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

/// chain[i] where vertex i ends a session (split_sessions).
inline constexpr std::size_t kNoStep = static_cast<std::size_t>(-1);

struct ChainSplit {
  std::vector<std::size_t> chain;     ///< chain[i]: index in graph.edges of the step i -> i+1
                                      ///< (kNoStep where vertex i ends a session)
  std::vector<std::size_t> closures;  ///< indices in graph.edges of the loop closures, in order
  std::vector<std::size_t> first{0};  ///< the first vertex of every session, ascending

  /// The session of `vertex` (an index into first).
  std::size_t session_of(std::size_t vertex) const;
};

/// Whether an edge joins consecutive vertices (odometry, always kept by the robust back ends).
inline bool is_odometry(const PoseGraphEdge& e) { return e.from + 1 == e.to || e.to + 1 == e.from; }

/// Throws std::runtime_error "source: no edge between vertices i and i+1 (...)" when the chain
/// is broken, and "source: ..." for a graph of fewer than 2 vertices.
ChainSplit split_chain(const PoseGraph& graph, const std::string& source);

/// A multi-session graph (several robots or runs: consecutive ids of different trajectories are
/// not joined) read as sessions, each a chain: the maximal runs of vertices whose consecutive
/// ids are joined by an edge (PCM's original use, Mangelson et al. 2018); for a graph that chains
/// every pose, split_chain's split. Throws std::runtime_error "source: ..." for a graph of fewer
/// than 2 vertices or a session of one vertex (a pose no odometry reaches).
ChainSplit split_sessions(const PoseGraph& graph, const std::string& source);

/// Poses in vertex 0's frame (vertex 0 at the identity) by composing the chain's steps; a
/// session after the first starts at the graph's own estimate of its first vertex.
std::vector<Pose2> chain_poses(const PoseGraph& graph, const ChainSplit& split);

}  // namespace antslam::slam
