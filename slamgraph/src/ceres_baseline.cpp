#include "antslam/slamgraph/ceres_baseline.hpp"

#include <ceres/ceres.h>
#include <glog/logging.h>

#include <stdexcept>

#include "ceres_residual.hpp"

namespace antslam::slam {

void show_solver_logs(bool show) {
  FLAGS_minloglevel = show ? google::GLOG_INFO : google::GLOG_FATAL;
}

CeresResult optimize_with_ceres(const FragmentSet& set, std::span<const Pose2> initial, bool robust,
                                const CeresSettings& settings) {
  validate(set);
  if (initial.size() != set.layer_count())
    throw std::invalid_argument("ceres: got " + std::to_string(initial.size()) +
                                " initial alignments, expected " +
                                std::to_string(set.layer_count()));
  if (settings.max_iterations <= 0) throw std::invalid_argument("ceres: max_iterations <= 0");
  std::vector<Eigen::Vector3d> poses;
  for (const Pose2& f : chain(initial)) poses.push_back(f.vector());

  ceres::Problem problem;
  const auto add = [&](std::size_t a, std::size_t b, const Pose2& anchor, const Gaussian2& g) {
    problem.AddResidualBlock(
        detail::RelativePoseError::create(anchor, g.mean(), g.information_factor()),
        robust ? new detail::WelschLoss : nullptr, poses[a].data(), poses[b].data());
  };
  for (std::size_t i = 1; i < set.fragments.size(); ++i)
    add(i - 1, i, Pose2{}, *set.fragments[i].alignment);
  for (const LoopClosure& c : set.closures) add(c.from, c.to, c.anchor, c.hypothesis);
  problem.SetParameterBlockConstant(poses[0].data());
  return detail::solve(problem, poses, settings);
}

namespace detail {

CeresResult solve(ceres::Problem& problem, std::vector<Eigen::Vector3d>& poses,
                  const CeresSettings& settings) {
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  options.max_num_iterations = settings.max_iterations;
  options.function_tolerance = settings.function_tolerance;
  if (settings.time_limit_s > 0.0) options.max_solver_time_in_seconds = settings.time_limit_s;
  options.logging_type = ceres::SILENT;
  options.num_threads = 1;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  if (!summary.IsSolutionUsable())
    throw std::runtime_error("ceres: no usable solution: " + summary.message);

  CeresResult result;
  for (const Eigen::Vector3d& p : poses) result.frames.push_back(Pose2::from_vector(p));
  result.final_cost = summary.final_cost;
  result.iterations = static_cast<int>(summary.iterations.size());
  result.converged = summary.termination_type == ceres::CONVERGENCE;
  return result;
}

}  // namespace detail

}  // namespace antslam::slam
