#include "slamgraph/ceres_baseline.hpp"

#include <ceres/ceres.h>
#include <glog/logging.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

namespace antslam::slam {

namespace {

/// U (F_a^-1 F_b A - H): the whitened residual of one alignment (A = identity, a = i - 1,
/// b = i) or one closure.
class RelativePoseError {
 public:
  RelativePoseError(const Pose2& anchor, const Gaussian2& gaussian)
      : anchor_(anchor), mean_(gaussian.mean()), sqrt_information_(gaussian.information_factor()) {}

  template <class T>
  bool operator()(const T* a, const T* b, T* residual) const {
    using std::cos, std::floor, std::sin;
    const T cb = cos(b[2]), sb = sin(b[2]);
    const T gx = b[0] + cb * anchor_.x - sb * anchor_.y;
    const T gy = b[1] + sb * anchor_.x + cb * anchor_.y;
    const T ca = cos(a[2]), sa = sin(a[2]);
    const T dx = gx - a[0], dy = gy - a[1];
    const T angle = b[2] + anchor_.theta - a[2] - mean_.theta;
    constexpr double kTwoPi = 2.0 * std::numbers::pi;
    Eigen::Matrix<T, 3, 1> r;
    r << ca * dx + sa * dy - mean_.x, -sa * dx + ca * dy - mean_.y,
        angle - kTwoPi * floor((angle + std::numbers::pi) / kTwoPi);
    Eigen::Map<Eigen::Matrix<T, 3, 1>> whitened(residual);
    whitened = sqrt_information_.cast<T>() * r;
    return true;
  }

  static ceres::CostFunction* create(const Pose2& anchor, const Gaussian2& gaussian) {
    return new ceres::AutoDiffCostFunction<RelativePoseError, 3, 3, 3>(
        new RelativePoseError(anchor, gaussian));
  }

 private:
  Pose2 anchor_;
  Pose2 mean_;
  Eigen::Matrix3d sqrt_information_;  // upper Cholesky factor U of Omega, U^T U = Omega
};

/// rho(s) = 2 (1 - exp(-s/2)): Ceres' 1/2 rho(|U r|^2) is the term 1 - N(mu, Sigma)(.) of
/// eq. (10).
class WelschLoss final : public ceres::LossFunction {
 public:
  void Evaluate(double s, double rho[3]) const override {
    const double e = std::exp(-0.5 * s);
    rho[0] = 2.0 * (1.0 - e);
    rho[1] = e;
    rho[2] = -0.5 * e;
  }
};

}  // namespace

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
    problem.AddResidualBlock(RelativePoseError::create(anchor, g),
                             robust ? new WelschLoss : nullptr, poses[a].data(), poses[b].data());
  };
  for (std::size_t i = 1; i < set.fragments.size(); ++i)
    add(i - 1, i, Pose2{}, *set.fragments[i].alignment);
  for (const LoopClosure& c : set.closures) add(c.from, c.to, c.anchor, c.hypothesis);
  problem.SetParameterBlockConstant(poses[0].data());

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

}  // namespace antslam::slam
