// Ceres on pose graphs under per-edge losses: the least-squares and M-estimator back ends.

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "antslam/slamgraph/ceres_baseline.hpp"
#include "ceres_residual.hpp"

namespace antslam::slam {

namespace {

/// Dynamic covariance scaling as a loss (EdgeLoss::Kind::dcs).
class DcsLoss final : public ceres::LossFunction {
 public:
  explicit DcsLoss(double phi) : phi_(phi) {}
  void Evaluate(double s, double rho[3]) const override {
    if (s <= phi_) {
      rho[0] = s;
      rho[1] = 1.0;
      rho[2] = 0.0;
      return;
    }
    const double d = phi_ + s;
    rho[0] = phi_ * (3.0 * s - phi_) / d;
    rho[1] = 4.0 * phi_ * phi_ / (d * d);
    rho[2] = -8.0 * phi_ * phi_ / (d * d * d);
  }

 private:
  double phi_;
};

/// rho(s) = w s (EdgeLoss::Kind::weighted).
class WeightedLoss final : public ceres::LossFunction {
 public:
  explicit WeightedLoss(double weight) : weight_(weight) {}
  void Evaluate(double s, double rho[3]) const override {
    rho[0] = weight_ * s;
    rho[1] = weight_;
    rho[2] = 0.0;
  }

 private:
  double weight_;
};

ceres::LossFunction* make_loss(const EdgeLoss& loss) {
  if (!(loss.parameter >= 0.0) || !std::isfinite(loss.parameter))
    throw std::invalid_argument("pose graph: a loss parameter is not a finite number >= 0");
  switch (loss.kind) {
    case EdgeLoss::Kind::squared:
      return nullptr;
    case EdgeLoss::Kind::cauchy:
      return new ceres::CauchyLoss(loss.parameter);
    case EdgeLoss::Kind::dcs:
      return new DcsLoss(loss.parameter);
    case EdgeLoss::Kind::weighted:
      return new WeightedLoss(loss.parameter);
  }
  return nullptr;
}

/// The residual of an edge as seen from its lower vertex: X_lo^-1 X_hi - z (inverted to first
/// order when stored the other way round, as the fragment-set importer does). On mit.g2o, whose
/// closures are all stored from the later vertex, Levenberg-Marquardt from odometry stops at
/// chi2 6694 with the stored direction and reaches 768 with this one.
struct ForwardEdge {
  std::size_t lo, hi;
  detail::RelativePoseError error;
};

ForwardEdge forward(const PoseGraphEdge& e) {
  const std::size_t lo = std::min(e.from, e.to), hi = std::max(e.from, e.to);
  const Gaussian2 z = oriented(e, lo);
  return {lo, hi, detail::RelativePoseError(Pose2{}, z.mean(), z.information_factor())};
}

}  // namespace

CeresResult optimize_pose_graph(const PoseGraph& graph, std::span<const Pose2> initial,
                                std::span<const EdgeLoss> losses, const CeresSettings& settings) {
  if (initial.size() != graph.vertices.size() || losses.size() != graph.edges.size())
    throw std::invalid_argument("pose graph: " + std::to_string(initial.size()) +
                                " initial poses and " + std::to_string(losses.size()) +
                                " losses for " + std::to_string(graph.vertices.size()) +
                                " vertices and " + std::to_string(graph.edges.size()) + " edges");
  if (settings.max_iterations <= 0) throw std::invalid_argument("ceres: max_iterations <= 0");
  std::vector<Eigen::Vector3d> poses;
  for (const Pose2& p : initial) poses.push_back(p.vector());
  // Every connected part of the graph the losses keep (sessions no kept edge joins) is held at
  // its lowest vertex; a graph that chains every pose has one part, held at vertex 0.
  std::vector<std::size_t> part(poses.size());
  for (std::size_t v = 0; v < part.size(); ++v) part[v] = v;
  const auto root = [&](std::size_t v) {
    while (part[v] != v) v = part[v] = part[part[v]];
    return v;
  };
  ceres::Problem problem;
  for (std::size_t e = 0; e < graph.edges.size(); ++e) {
    if (losses[e].kind == EdgeLoss::Kind::weighted && losses[e].parameter == 0.0) continue;
    const ForwardEdge edge = forward(graph.edges[e]);
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<detail::RelativePoseError, 3, 3, 3>(
                                 new detail::RelativePoseError(edge.error)),
                             make_loss(losses[e]), poses[edge.lo].data(), poses[edge.hi].data());
    const std::size_t a = root(edge.lo), b = root(edge.hi);
    part[std::max(a, b)] = std::min(a, b);  // the lowest vertex stays the root
  }
  for (std::size_t v = 0; v < poses.size(); ++v)
    if (root(v) == v && problem.HasParameterBlock(poses[v].data()))
      problem.SetParameterBlockConstant(poses[v].data());
  return detail::solve(problem, poses, settings);
}

std::vector<double> edge_chi2(const PoseGraph& graph, std::span<const Pose2> poses) {
  if (poses.size() != graph.vertices.size())
    throw std::invalid_argument("pose graph: " + std::to_string(poses.size()) + " poses for " +
                                std::to_string(graph.vertices.size()) + " vertices");
  std::vector<double> chi2;
  chi2.reserve(graph.edges.size());
  for (const PoseGraphEdge& e : graph.edges) {
    const ForwardEdge edge = forward(e);
    const Eigen::Vector3d a = poses[edge.lo].vector(), b = poses[edge.hi].vector();
    Eigen::Vector3d r;
    edge.error(a.data(), b.data(), r.data());
    chi2.push_back(r.squaredNorm());
  }
  return chi2;
}

ResidualSummary residual_summary(const PoseGraph& graph, std::span<const Pose2> poses) {
  ResidualSummary summary;
  for (const double c : edge_chi2(graph, poses)) summary.chi2 += c;
  summary.degrees_of_freedom = 3 * static_cast<std::int64_t>(graph.edges.size()) -
                               3 * (static_cast<std::int64_t>(graph.vertices.size()) - 1);
  if (summary.degrees_of_freedom > 0)
    summary.variance_factor = summary.chi2 / static_cast<double>(summary.degrees_of_freedom);
  return summary;
}

}  // namespace antslam::slam
