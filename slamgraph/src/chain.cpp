#include "antslam/slamgraph/chain.hpp"

#include <algorithm>
#include <stdexcept>

namespace antslam::slam {

namespace {

/// The odometry steps, the closures and the sessions' first vertices (unchecked).
ChainSplit split_edges(const PoseGraph& graph, const std::string& source) {
  const std::size_t n = graph.vertices.size();
  if (n < 2) throw std::runtime_error(source + ": a pose graph needs at least 2 vertices");
  ChainSplit split;
  split.chain.assign(n - 1, kNoStep);
  for (std::size_t e = 0; e < graph.edges.size(); ++e) {
    const PoseGraphEdge& edge = graph.edges[e];
    if (!is_odometry(edge)) {
      split.closures.push_back(e);
    } else if (std::size_t& step = split.chain[std::min(edge.from, edge.to)]; step == kNoStep) {
      step = e;
    }
  }
  for (std::size_t i = 0; i + 1 < n; ++i)
    if (split.chain[i] == kNoStep) split.first.push_back(i + 1);
  return split;
}

}  // namespace

ChainSplit split_chain(const PoseGraph& graph, const std::string& source) {
  ChainSplit split = split_edges(graph, source);
  if (split.first.size() > 1)
    throw std::runtime_error(
        source + ": no edge between vertices " + std::to_string(split.first[1] - 1) + " and " +
        std::to_string(split.first[1]) + " (the graph must chain consecutive poses)");
  return split;
}

ChainSplit split_sessions(const PoseGraph& graph, const std::string& source) {
  ChainSplit split = split_edges(graph, source);
  const std::size_t n = graph.vertices.size();
  for (std::size_t k = 0; k < split.first.size(); ++k) {
    const std::size_t end = k + 1 < split.first.size() ? split.first[k + 1] : n;
    if (end - split.first[k] < 2)
      throw std::runtime_error(source + ": vertex " + std::to_string(split.first[k]) +
                               " has no edge to the vertex before or after it (a session of "
                               "one pose)");
  }
  return split;
}

std::vector<Pose2> chain_poses(const PoseGraph& graph, const ChainSplit& split) {
  std::vector<Pose2> poses(graph.vertices.size());
  for (std::size_t i = 0; i < split.chain.size(); ++i)
    poses[i + 1] = split.chain[i] == kNoStep
                       ? graph.vertices[0].inverse() * graph.vertices[i + 1]
                       : poses[i] * oriented(graph.edges[split.chain[i]], i).mean();
  return poses;
}

std::size_t ChainSplit::session_of(std::size_t vertex) const {
  return static_cast<std::size_t>(std::upper_bound(first.begin(), first.end(), vertex) -
                                  first.begin()) -
         1;
}

}  // namespace antslam::slam
