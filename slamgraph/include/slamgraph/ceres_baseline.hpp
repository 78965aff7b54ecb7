#pragma once
// Ceres pose-graph optimisation on the same graph: the comparison with
// state-of-the-art optimisation that the paper asks for (Sec. V).
//
// Unknowns: the world poses of F_2..F_N (F_1 = W is held constant). Residual blocks: one per
// alignment, r = F_{i-1}^-1 F_i - mu_i, and one per closure, r = F_a^-1 F_b A - H (angles
// wrapped), each whitened by the upper Cholesky factor U of its information matrix,
// U^T U = Omega, so that |U r|^2 = r^T Omega r. (Ceres' own pose_graph_2d example uses the lower
// factor L of Omega; |L r|^2 = r^T L^T L r differs from r^T Omega r whenever Omega has
// off-diagonal terms.) Two forms:
//   plain   Ceres minimises 1/2 sum r^T Omega r = chi2 / 2 (least squares);
//   robust  each block under the Welsch-type loss rho(s) = 2 (1 - exp(-s / 2)), so Ceres
//           minimises 1/2 sum rho(s) = sum (1 - exp(-s / 2)), exactly the weight of eq. (10).

#include <span>
#include <string>
#include <vector>

#include "slamgraph/fragment_set.hpp"

namespace antslam::slam {

struct CeresSettings {
  int max_iterations = 200;           ///< Levenberg-Marquardt iterations (count)
  double function_tolerance = 1e-12;  ///< stop when the cost changes by less (fraction)
  double time_limit_s = 0.0;          ///< wall-clock budget in seconds; 0 = none
};

struct CeresResult {
  std::vector<Pose2> frames;  ///< optimised world poses of F_1..F_N
  double final_cost = 0.0;    ///< Ceres' cost: chi2 / 2 (plain) or the eq. (10) weight (robust)
  int iterations = 0;         ///< solver iterations
  bool converged = false;     ///< Ceres reported convergence
};

/// Whether Ceres prints its own warnings and diagnostics (through glog) on stderr. They are
/// shown unless this is called with false; antslam shows them only with --verbose, so that a
/// failure is the one line its error names.
void show_solver_logs(bool show);

/// Runs Ceres from the world frames that `initial` alignments chain to (alignments.size() ==
/// N - 1). Throws std::invalid_argument on wrong sizes, std::runtime_error if Ceres fails.
CeresResult optimize_with_ceres(const FragmentSet& set, std::span<const Pose2> initial, bool robust,
                                const CeresSettings& settings);

}  // namespace antslam::slam
