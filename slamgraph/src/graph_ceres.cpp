#include "graph_ceres.hpp"

#include <ceres/ceres.h>

#include <Eigen/Cholesky>
#include <stdexcept>

#include "antslam/slamgraph/graph_structure.hpp"
#include "ceres_residual.hpp"

namespace antslam::slam::detail {

CeresResult optimize_graph_with_ceres(const PoseGraph& graph, bool robust,
                                      const CeresSettings& settings) {
  if (settings.max_iterations <= 0) throw std::invalid_argument("ceres: max_iterations <= 0");
  std::vector<Eigen::Vector3d> poses;
  for (const Pose2& p : graph.vertices) poses.push_back(p.vector());
  ceres::Problem problem;
  for (const OrientedEdge& e : oriented_edges(graph)) {
    // U with U^T U = Omega: the transposed lower Cholesky factor of Omega.
    const Eigen::Matrix3d upper = e.information.llt().matrixL().transpose();
    problem.AddResidualBlock(RelativePoseError::create(Pose2{}, e.mean, upper),
                             robust ? new WelschLoss : nullptr, poses[e.lo].data(),
                             poses[e.hi].data());
  }
  std::size_t held = 0;
  for (const std::size_t v : fixed_vertices(graph)) {
    if (!problem.HasParameterBlock(poses[v].data())) continue;
    problem.SetParameterBlockConstant(poses[v].data());
    ++held;
  }
  if (held == static_cast<std::size_t>(problem.NumParameterBlocks())) {
    CeresResult unchanged;
    unchanged.frames = graph.vertices;
    unchanged.converged = true;
    return unchanged;
  }
  return solve(problem, poses, settings);
}

}  // namespace antslam::slam::detail
