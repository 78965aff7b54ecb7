// Graduated non-convexity with the truncated-least-squares cost (Yang, Antonante, Tzoumas and
// Carlone 2020, GNC-TLS): the cost of a closure with squared residual r2 is min(r2, c2); its GNC
// surrogate with parameter mu is convex for small mu and the TLS cost as mu -> infinity. Each
// step solves the weighted least-squares problem with the current closure weights, then sets
//   w = 1                                    for r2 <= mu / (mu + 1) c2,
//   w = sqrt(c2 mu (mu + 1) / r2) - mu       in between,
//   w = 0                                    for r2 >= (mu + 1) / mu c2,
// and multiplies mu by mu_factor, starting from mu = c2 / (2 r2_max - c2) after plain least
// squares. It stops when every weight is 0 or 1 (within weight_tolerance) and the solve used
// them; a closure whose final weight exceeds 1/2 is accepted, and a last solve to convergence
// runs on the odometry and the accepted closures. The steps solve only step_iterations
// Levenberg-Marquardt iterations each from where the last step ended (the weights move little
// between steps); on a graph with many false closures a solve to convergence of every step
// would cost minutes, because the false closures fill the sparse factorisation in.

#include <algorithm>
#include <cmath>

#include "robust_detail.hpp"

namespace antslam::slam::detail {

namespace {

double tls_weight(double r2, double c2, double mu) {
  if (r2 <= mu / (mu + 1.0) * c2) return 1.0;
  if (r2 >= (mu + 1.0) / mu * c2) return 0.0;
  return std::sqrt(c2 * mu * (mu + 1.0) / r2) - mu;
}

}  // namespace

void run_gnc(const PoseGraph& graph, const std::vector<Pose2>& initial, double c2,
             const RobustSettings& settings, RobustResult& result) {
  const std::size_t m = result.split.closures.size();
  RobustSettings per_step = settings;
  per_step.ceres.max_iterations = settings.gnc.step_iterations;
  std::vector<EdgeLoss> weight(m, EdgeLoss{EdgeLoss::Kind::weighted, 1.0});
  optimize(graph, initial, edge_losses(graph, result.split, weight), per_step, result);
  std::vector<double> r2 = closure_chi2(graph, result.split, result.poses);
  const double r2_max = r2.empty() ? 0.0 : *std::max_element(r2.begin(), r2.end());
  double mu = 2.0 * r2_max > c2 ? c2 / (2.0 * r2_max - c2) : 0.0;
  if (mu > 0.0) {  // else every closure is within the truncation: least squares is TLS
    for (std::size_t step = 1; step <= settings.gnc.max_steps; ++step) {
      bool decided = true;
      for (std::size_t k = 0; k < m; ++k) {
        const double w = tls_weight(r2[k], c2, mu);
        weight[k].parameter = w;
        decided = decided &&
                  (w <= settings.gnc.weight_tolerance || w >= 1.0 - settings.gnc.weight_tolerance);
      }
      optimize(graph, result.poses, edge_losses(graph, result.split, weight), per_step, result);
      result.gnc_steps = step;
      if (decided) break;
      r2 = closure_chi2(graph, result.split, result.poses);
      mu *= settings.gnc.mu_factor;
    }
  }
  result.accepted.resize(m);
  for (std::size_t k = 0; k < m; ++k) {
    result.accepted[k] = weight[k].parameter > 0.5;
    weight[k].parameter = result.accepted[k] ? 1.0 : 0.0;
  }
  optimize(graph, result.poses, edge_losses(graph, result.split, weight), settings, result);
}

}  // namespace antslam::slam::detail
