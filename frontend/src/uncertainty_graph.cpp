#include "antslam/frontend/uncertainty_graph.hpp"

#include <functional>
#include <queue>
#include <stdexcept>
#include <utility>

#include "antslam/frontend/pose_covariance.hpp"

namespace antslam::frontend {

std::vector<RelativeEstimate> relative_to(std::size_t target, std::size_t nodes,
                                          std::span<const GraphEdge> edges) {
  if (target >= nodes) throw std::invalid_argument("relative_to: target out of range");
  // Neighbours with the pose of the neighbour's frame in this node's frame.
  struct Link {
    std::size_t node;
    slam::Pose2 pose;
    Eigen::Matrix3d covariance;
  };
  std::vector<std::vector<Link>> links(nodes);
  for (const GraphEdge& e : edges) {
    if (e.from >= nodes || e.to >= nodes) continue;
    links[e.from].push_back({e.to, e.relative, e.covariance});
    links[e.to].push_back(
        {e.from, e.relative.inverse(), inverse_covariance(e.relative, e.covariance)});
  }
  std::vector<RelativeEstimate> out(nodes);
  out[target] = {true, slam::Pose2{}, Eigen::Matrix3d::Zero()};
  std::vector<bool> done(nodes, false);
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  queue.push({0.0, target});
  while (!queue.empty()) {
    const std::size_t m = queue.top().second;
    queue.pop();
    if (done[m]) continue;
    done[m] = true;
    // Relax n -> m: F_target in F_n = (F_m in F_n) * (F_target in F_m).
    for (const Link& link : links[m]) {
      const std::size_t n = link.node;
      if (done[n]) continue;
      const slam::Pose2 m_in_n = link.pose.inverse();
      const Eigen::Matrix3d m_in_n_cov = inverse_covariance(link.pose, link.covariance);
      const Eigen::Matrix3d cov =
          compose_covariance(m_in_n, m_in_n_cov, out[m].pose, out[m].covariance);
      const double cost = cov(0, 0) + cov(1, 1);
      if (!out[n].reachable || cost < out[n].covariance(0, 0) + out[n].covariance(1, 1)) {
        out[n] = {true, m_in_n * out[m].pose, cov};
        queue.push({cost, n});
      }
    }
  }
  return out;
}

}  // namespace antslam::frontend
