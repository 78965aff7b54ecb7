#include "antslam/slamgraph/graph_objective.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "antslam/slamgraph/graph_structure.hpp"

namespace antslam::slam {

GraphObjective::GraphObjective(const PoseGraph& graph)
    : graph_(&graph),
      edges_(oriented_edges(graph)),
      slot_(graph.vertices.size(), 0),
      poses_(3 * graph.vertices.size()) {
  for (const std::size_t f : fixed_vertices(graph)) {
    if (f >= graph.vertices.size())
      throw std::invalid_argument("pose graph: fixed vertex " + std::to_string(f) +
                                  " is not in the graph");
    slot_[f] = -1;
  }
  for (std::size_t v = 0; v < graph.vertices.size(); ++v) {
    const Pose2& p = graph.vertices[v];
    std::copy_n(p.vector().data(), 3, poses_.data() + 3 * v);
    if (slot_[v] < 0) continue;
    slot_[v] = static_cast<std::ptrdiff_t>(free_.size());
    free_.push_back(v);
  }
}

void GraphObjective::set_kernel_width(double width) {
  if (!(width > 0.0) || !std::isfinite(width))
    throw std::invalid_argument("kernel width must be a positive number");
  width_ = width;
}

std::vector<double> GraphObjective::pack(std::span<const Pose2> poses) const {
  if (poses.size() != graph_->vertices.size())
    throw std::invalid_argument("pose graph: got " + std::to_string(poses.size()) + " poses for " +
                                std::to_string(graph_->vertices.size()) + " vertices");
  std::vector<double> x;
  x.reserve(dimension());
  for (const std::size_t v : free_) x.insert(x.end(), {poses[v].x, poses[v].y, poses[v].theta});
  return x;
}

std::vector<Pose2> GraphObjective::unpack(std::span<const double> x) const {
  if (x.size() != dimension())
    throw std::invalid_argument("pose vector has " + std::to_string(x.size()) +
                                " entries, expected " + std::to_string(dimension()));
  std::vector<Pose2> poses = graph_->vertices;
  for (std::size_t k = 0; k < free_.size(); ++k)
    poses[free_[k]] = Pose2::from_vector({x[3 * k], x[3 * k + 1], x[3 * k + 2]});
  return poses;
}

Scores GraphObjective::evaluate(std::span<const double> x, std::span<double> gradient) {
  if (x.size() != dimension())
    throw std::invalid_argument("pose vector has " + std::to_string(x.size()) +
                                " entries, expected " + std::to_string(dimension()));
  const bool with_gradient = !gradient.empty();
  if (with_gradient && gradient.size() != x.size())
    throw std::invalid_argument("gradient size differs from the pose vector");
  for (std::size_t k = 0; k < free_.size(); ++k) std::copy_n(&x[3 * k], 3, &poses_[3 * free_[k]]);
  if (with_gradient) std::fill(gradient.begin(), gradient.end(), 0.0);
  const double w2 = width_ * width_;
  Scores scores;
  for (const OrientedEdge& e : edges_) {
    const double* a = &poses_[3 * e.lo];
    const double* b = &poses_[3 * e.hi];
    const double c = std::cos(a[2]), s = std::sin(a[2]);
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double d_x = c * dx + s * dy, d_y = -s * dx + c * dy;  // d = R_i^T (t_j - t_i)
    const Pose2& z = e.mean;
    const Eigen::Vector3d r(d_x - z.x, d_y - z.y, wrap_angle(b[2] - a[2] - z.theta));
    const Eigen::Vector3d omega_r = e.information * r;
    const double m = r.dot(omega_r);
    // The peak-normalised N(mu, Sigma)(.) of eq. (10), at width 1.
    const double value = std::exp(-0.5 * m / w2);
    scores.chi2 += m;
    scores.weight += w2 * (1.0 - value);
    if (!with_gradient) continue;
    const Eigen::Vector3d g = value * omega_r;
    const double gx = c * g.x() - s * g.y(), gy = s * g.x() + c * g.y();  // R_i g_xy
    if (const std::ptrdiff_t k = slot_[e.hi]; k >= 0) {
      double* gj = &gradient[3 * static_cast<std::size_t>(k)];
      gj[0] += gx;
      gj[1] += gy;
      gj[2] += g.z();
    }
    if (const std::ptrdiff_t k = slot_[e.lo]; k >= 0) {
      double* gi = &gradient[3 * static_cast<std::size_t>(k)];
      gi[0] -= gx;
      gi[1] -= gy;
      gi[2] += g.x() * d_y - g.y() * d_x - g.z();
    }
  }
  return scores;
}

}  // namespace antslam::slam
