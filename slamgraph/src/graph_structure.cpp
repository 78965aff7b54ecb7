#include "antslam/slamgraph/graph_structure.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <stdexcept>

#include "antslam/slamgraph/chain.hpp"

namespace antslam::slam {

namespace {

/// Edges by vertex: incident[offset[v] .. offset[v + 1]) are the edges that touch v.
struct Incidence {
  std::vector<std::size_t> offset;
  std::vector<std::size_t> incident;

  explicit Incidence(const PoseGraph& graph) : offset(graph.vertices.size() + 1, 0) {
    for (const PoseGraphEdge& e : graph.edges) {
      ++offset[e.from + 1];
      ++offset[e.to + 1];
    }
    for (std::size_t v = 0; v < graph.vertices.size(); ++v) offset[v + 1] += offset[v];
    incident.resize(offset.back());
    std::vector<std::size_t> next(offset.begin(), offset.end() - 1);
    for (std::size_t k = 0; k < graph.edges.size(); ++k) {
      incident[next[graph.edges[k].from]++] = k;
      incident[next[graph.edges[k].to]++] = k;
    }
  }
  std::span<const std::size_t> of(std::size_t v) const {
    return std::span(incident).subspan(offset[v], offset[v + 1] - offset[v]);
  }
};

/// The vertex at the other end of edge e from v.
std::size_t other_end(const PoseGraphEdge& e, std::size_t v) { return e.from == v ? e.to : e.from; }

/// Breadth-first search over the edges from `roots`; returns which vertices it reached.
std::vector<bool> reached_from(const PoseGraph& graph, std::span<const std::size_t> roots) {
  const Incidence incidence(graph);
  std::vector<bool> reached(graph.vertices.size(), false);
  std::deque<std::size_t> queue(roots.begin(), roots.end());
  for (const std::size_t r : roots) reached[r] = true;
  while (!queue.empty()) {
    const std::size_t v = queue.front();
    queue.pop_front();
    for (const std::size_t k : incidence.of(v)) {
      const std::size_t u = other_end(graph.edges[k], v);
      if (reached[u]) continue;
      reached[u] = true;
      queue.push_back(u);
    }
  }
  return reached;
}

}  // namespace

std::vector<std::size_t> fixed_vertices(const PoseGraph& graph) {
  if (!graph.fixed.empty()) return graph.fixed;
  return {0};
}

std::vector<Pose2> spanning_tree_poses(const PoseGraph& graph, const std::string& source) {
  const std::size_t n = graph.vertices.size();
  const Incidence incidence(graph);
  // 0-1 breadth-first search: an odometry edge costs 0, any other 1, so that each vertex is
  // reached over the fewest non-odometry edges and its tree edge is odometry wherever it can be.
  constexpr std::size_t kUnreached = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> cost(n, kUnreached), tree_edge(n, kUnreached), order;
  std::vector<bool> done(n, false);
  std::deque<std::size_t> queue{0};
  cost[0] = 0;
  while (!queue.empty()) {
    const std::size_t v = queue.front();
    queue.pop_front();
    if (done[v]) continue;
    done[v] = true;
    order.push_back(v);
    for (const std::size_t k : incidence.of(v)) {
      const PoseGraphEdge& e = graph.edges[k];
      const std::size_t u = other_end(e, v);
      const std::size_t step = is_odometry(e) ? 0 : 1;
      if (done[u] || cost[v] + step >= cost[u]) continue;
      cost[u] = cost[v] + step;
      tree_edge[u] = k;
      if (step == 0) {
        queue.push_front(u);
      } else {
        queue.push_back(u);
      }
    }
  }
  for (std::size_t v = 0; v < n; ++v)
    if (!done[v])
      throw std::runtime_error(source + ": vertex " + std::to_string(v) +
                               " is joined to vertex 0 by no chain of edges, so it has no "
                               "initial pose (the file has no vertex lines)");
  // Vertices leave the queue after their tree parent, so one pass in that order places them.
  std::vector<Pose2> poses(n);
  for (const std::size_t v : order) {
    if (v == 0) continue;
    const PoseGraphEdge& e = graph.edges[tree_edge[v]];
    poses[v] = e.to == v ? poses[e.from] * e.measurement : poses[e.to] * e.measurement.inverse();
  }
  return poses;
}

void check_anchored(const PoseGraph& graph, const std::string& source) {
  const std::vector<std::size_t> fixed = fixed_vertices(graph);
  for (const std::size_t f : fixed)
    if (f >= graph.vertices.size())
      throw std::invalid_argument(source + ": fixed vertex " + std::to_string(f) +
                                  " is not in the graph");
  const std::vector<bool> reached = reached_from(graph, fixed);
  for (std::size_t v = 0; v < reached.size(); ++v)
    if (!reached[v])
      throw std::invalid_argument(
          source + ": vertex " + std::to_string(v) +
          " is joined to no fixed vertex by edges, so its pose is undetermined (connect the "
          "graph, or FIX a vertex of each part)");
}

std::vector<OrientedEdge> oriented_edges(const PoseGraph& graph) {
  std::vector<OrientedEdge> edges;
  edges.reserve(graph.edges.size());
  for (const PoseGraphEdge& e : graph.edges) {
    const std::size_t lo = std::min(e.from, e.to), hi = std::max(e.from, e.to);
    if (e.from == lo) {
      edges.push_back({lo, hi, e.measurement, e.information});
    } else {
      const Gaussian2 g = oriented(e, lo);
      edges.push_back({lo, hi, g.mean(), g.information()});
    }
  }
  return edges;
}

Eigen::Vector3d edge_residual(const OrientedEdge& edge, const Pose2& lo, const Pose2& hi) {
  const double c = std::cos(lo.theta), s = std::sin(lo.theta);
  const double dx = hi.x - lo.x, dy = hi.y - lo.y;
  const Pose2& z = edge.mean;
  return {c * dx + s * dy - z.x, -s * dx + c * dy - z.y, wrap_angle(hi.theta - lo.theta - z.theta)};
}

Scores score(const PoseGraph& graph, std::span<const Pose2> poses) {
  if (poses.size() != graph.vertices.size())
    throw std::invalid_argument("pose graph: got " + std::to_string(poses.size()) + " poses for " +
                                std::to_string(graph.vertices.size()) + " vertices");
  Scores s;
  for (const OrientedEdge& e : oriented_edges(graph)) {
    const Eigen::Vector3d r = edge_residual(e, poses[e.lo], poses[e.hi]);
    const double m = r.dot(e.information * r);
    s.chi2 += m;
    s.weight += 1.0 - std::exp(-0.5 * m);
  }
  return s;
}

}  // namespace antslam::slam
