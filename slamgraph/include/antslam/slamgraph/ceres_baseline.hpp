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

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "antslam/slamgraph/fragment_set.hpp"
#include "antslam/slamgraph/g2o.hpp"

namespace antslam::slam {

struct CeresSettings {
  int max_iterations = 200;           ///< Levenberg-Marquardt iterations (count)
  double function_tolerance = 1e-12;  ///< stop when the cost changes by less (fraction)
  double time_limit_s = 0.0;          ///< wall-clock budget in seconds; 0 = none
};

struct CeresResult {
  std::vector<Pose2> frames;  ///< optimised world poses of F_1..F_N (of the vertices)
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

/// The loss of one pose-graph edge on its squared whitened residual s = r^T Omega r; Ceres
/// minimises 1/2 sum rho(s).
struct EdgeLoss {
  enum class Kind {
    squared,   ///< rho(s) = s: least squares
    cauchy,    ///< rho(s) = c^2 log(1 + s / c^2), c = parameter (Ceres' CauchyLoss)
    dcs,       ///< dynamic covariance scaling (Agarwal et al. 2013), Phi = parameter: rho(s) = s
               ///< for s <= Phi, else Phi (3 s - Phi) / (Phi + s); its weight rho'(s) =
               ///< (2 Phi / (Phi + s))^2 is the square of DCS's scale (MacTavish & Barfoot 2015)
    weighted,  ///< rho(s) = w s, w = parameter >= 0 (the weights of graduated non-convexity)
  };
  Kind kind = Kind::squared;  ///< which loss
  double parameter = 1.0;     ///< c (chi units), Phi (chi^2 units) or w (dimensionless)
};

/// Ceres on a pose graph: one residual per edge, r = X_a^-1 X_b - z (angle wrapped, a < b: an
/// edge stored from the higher vertex is inverted to first order) whitened by the upper Cholesky
/// factor of its information matrix, under losses[e] (an edge weighted 0 is left out of the
/// problem: the same optimum without its fill-in of the sparse factorisation); vertex 0 held
/// constant;
/// started from `initial` (one pose per vertex). Throws std::invalid_argument on wrong sizes,
/// std::runtime_error if Ceres fails.
CeresResult optimize_pose_graph(const PoseGraph& graph, std::span<const Pose2> initial,
                                std::span<const EdgeLoss> losses, const CeresSettings& settings);

/// r^T Omega r of every edge at the vertex poses `poses` (the residual of optimize_pose_graph).
std::vector<double> edge_chi2(const PoseGraph& graph, std::span<const Pose2> poses);

/// How well the poses fit the edges against the noise the graph states.
struct ResidualSummary {
  double chi2 = 0.0;                    ///< sum of r^T Omega r over the edges (edge_chi2)
  std::int64_t degrees_of_freedom = 0;  ///< 3 per edge - 3 per vertex but vertex 0 (held)
  /// chi2 / degrees of freedom, the a posteriori variance factor of a least-squares solution:
  /// about 1 when the graph states its noise as it is, 1/k^2 when k times too wide; none
  /// without redundancy (no more edges than a spanning chain).
  std::optional<double> variance_factor;
};

/// The residual summary of the poses on the graph (a connected graph: a chain at least).
ResidualSummary residual_summary(const PoseGraph& graph, std::span<const Pose2> poses);

}  // namespace antslam::slam
