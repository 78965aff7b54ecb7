#include "antslam/slamgraph/chain.hpp"

#include <limits>
#include <stdexcept>

namespace antslam::slam {

ChainSplit split_chain(const PoseGraph& graph, const std::string& source) {
  const std::size_t n = graph.vertices.size();
  if (n < 2) throw std::runtime_error(source + ": a pose graph needs at least 2 vertices");
  constexpr std::size_t kMissing = std::numeric_limits<std::size_t>::max();
  ChainSplit split;
  split.chain.assign(n - 1, kMissing);
  for (std::size_t e = 0; e < graph.edges.size(); ++e) {
    const PoseGraphEdge& edge = graph.edges[e];
    if (!is_odometry(edge)) {
      split.closures.push_back(e);
    } else if (std::size_t& step = split.chain[std::min(edge.from, edge.to)]; step == kMissing) {
      step = e;
    }
  }
  for (std::size_t i = 0; i + 1 < n; ++i)
    if (split.chain[i] == kMissing)
      throw std::runtime_error(source + ": no edge between vertices " + std::to_string(i) +
                               " and " + std::to_string(i + 1) +
                               " (the graph must chain consecutive poses)");
  return split;
}

std::vector<Pose2> chain_poses(const PoseGraph& graph, const ChainSplit& split) {
  std::vector<Pose2> poses(graph.vertices.size());
  for (std::size_t i = 0; i < split.chain.size(); ++i)
    poses[i + 1] = poses[i] * oriented(graph.edges[split.chain[i]], i).mean();
  return poses;
}

}  // namespace antslam::slam
