#include "antslam/slamgraph/robust.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "antslam/slamgraph/chi_square.hpp"
#include "antslam/slamgraph/name_table.hpp"
#include "robust_detail.hpp"

namespace antslam::slam {

std::string_view to_string(RobustMethod method) { return detail::name_in(kRobustMethods, method); }

std::optional<RobustMethod> parse_robust_method(std::string_view name) {
  return detail::value_in(kRobustMethods, name);
}

namespace detail {

std::vector<EdgeLoss> edge_losses(const PoseGraph& graph, const ChainSplit& split,
                                  const std::vector<EdgeLoss>& closure_loss) {
  std::vector<EdgeLoss> losses(graph.edges.size());
  for (std::size_t k = 0; k < split.closures.size(); ++k)
    losses[split.closures[k]] = closure_loss[k];
  return losses;
}

double optimize(const PoseGraph& graph, const std::vector<Pose2>& initial,
                const std::vector<EdgeLoss>& losses, const RobustSettings& settings,
                RobustResult& result) {
  const auto start = std::chrono::steady_clock::now();
  CeresResult solved = optimize_pose_graph(graph, initial, losses, settings.ceres);
  result.poses = std::move(solved.frames);
  result.optimize_s += seconds_since(start);
  return solved.final_cost;
}

std::vector<double> closure_chi2(const PoseGraph& graph, const ChainSplit& split,
                                 const std::vector<Pose2>& poses) {
  const std::vector<double> all = edge_chi2(graph, poses);
  std::vector<double> chi2;
  for (const std::size_t e : split.closures) chi2.push_back(all[e]);
  return chi2;
}

std::vector<bool> closures_within(const PoseGraph& graph, const ChainSplit& split,
                                  const std::vector<Pose2>& poses, double c2) {
  const std::vector<double> chi2 = closure_chi2(graph, split, poses);
  std::vector<bool> within(chi2.size());
  for (std::size_t k = 0; k < chi2.size(); ++k) within[k] = chi2[k] <= c2;
  return within;
}

}  // namespace detail

namespace {

void validate(const RobustSettings& s) {
  if (!(s.inlier_confidence > 0.0 && s.inlier_confidence < 1.0))
    throw std::invalid_argument("robust: inlier confidence must be in (0, 1)");
  if (!(std::isfinite(s.cauchy_scale) && s.cauchy_scale > 0.0))
    throw std::invalid_argument("robust: the Cauchy scale must be a finite positive number");
  if (!(std::isfinite(s.dcs_phi) && s.dcs_phi > 0.0))
    throw std::invalid_argument("robust: DCS Phi must be a finite positive number");
  if (!(std::isfinite(s.gnc.mu_factor) && s.gnc.mu_factor > 1.0) || s.gnc.max_steps == 0 ||
      s.gnc.step_iterations <= 0)
    throw std::invalid_argument(
        "robust: GNC needs a mu factor > 1, at least one step and one iteration per step");
  if (!(std::isfinite(s.check_phi) && s.check_phi >= 0.0))
    throw std::invalid_argument("robust: the check's Phi must be a finite number >= 0");
  if (!(s.recalibrate_below >= 0.0))
    throw std::invalid_argument("robust: the recalibration threshold must be a number >= 0");
  const clique::AcoSearchSettings ants;
  if ((s.aco.backend != ants.backend && s.aco.backend != s.backend) ||
      (s.aco.threads != ants.threads && s.aco.threads != s.threads))
    throw std::invalid_argument(
        "robust: set the backend and threads of the settings themselves (they run the "
        "consistency pairs and the ants), not those of its aco member");
  if (s.check_start_iterations <= 0)
    throw std::invalid_argument("robust: the clique check needs at least one start iteration");
}

/// The odometry chain placed at vertex 0's pose: where every method starts.
std::vector<Pose2> odometry_start(const PoseGraph& graph, const ChainSplit& split) {
  std::vector<Pose2> poses = chain_poses(graph, split);
  for (Pose2& p : poses) p = graph.vertices[0] * p;
  return poses;
}

/// ls, cauchy and dcs: one solve under one closure loss; a closure is accepted when it passes
/// the chi-square test at the end (ls accepts every closure).
void run_m_estimator(const PoseGraph& graph, const std::vector<Pose2>& initial, EdgeLoss loss,
                     double c2, const RobustSettings& settings, RobustResult& result) {
  const std::size_t m = result.split.closures.size();
  detail::optimize(graph, initial,
                   detail::edge_losses(graph, result.split, std::vector<EdgeLoss>(m, loss)),
                   settings, result);
  if (loss.kind == EdgeLoss::Kind::squared) {
    result.accepted.assign(m, true);
    return;
  }
  result.accepted = detail::closures_within(graph, result.split, result.poses, c2);
}

}  // namespace

RobustResult solve_robust(const PoseGraph& graph, RobustMethod method,
                          const RobustSettings& settings, const std::string& source) {
  validate(settings);
  const auto start = std::chrono::steady_clock::now();
  RobustResult result;
  result.method = method;
  result.split = split_sessions(graph, source);
  const std::vector<Pose2> initial = odometry_start(graph, result.split);
  const double c2 = chi_square3_quantile(settings.inlier_confidence);
  switch (method) {
    case RobustMethod::ls:
      run_m_estimator(graph, initial, {}, c2, settings, result);
      break;
    case RobustMethod::cauchy:
      run_m_estimator(graph, initial, {EdgeLoss::Kind::cauchy, settings.cauchy_scale}, c2, settings,
                      result);
      break;
    case RobustMethod::dcs:
      run_m_estimator(graph, initial, {EdgeLoss::Kind::dcs, settings.dcs_phi}, c2, settings,
                      result);
      break;
    case RobustMethod::gnc:
      detail::run_gnc(graph, initial, c2, settings, result);
      break;
    case RobustMethod::pcm_exact:
    case RobustMethod::pcm_aco:
      detail::run_pcm(graph, initial, c2, settings, result);
      break;
  }
  result.total_s = detail::seconds_since(start);
  return result;
}

PoseGraph kept_graph(const PoseGraph& graph, const RobustResult& result) {
  std::vector<bool> keep(graph.edges.size(), true);
  for (std::size_t k = 0; k < result.split.closures.size(); ++k)
    keep[result.split.closures[k]] = result.accepted[k];
  PoseGraph kept;
  kept.vertices = result.poses;
  for (std::size_t e = 0; e < graph.edges.size(); ++e)
    if (keep[e]) kept.edges.push_back(graph.edges[e]);
  return kept;
}

AcceptanceScores score_acceptance(const std::vector<bool>& accepted,
                                  const std::vector<bool>& outlier) {
  if (accepted.size() != outlier.size())
    throw std::invalid_argument("acceptance scores: " + std::to_string(accepted.size()) +
                                " decisions for " + std::to_string(outlier.size()) + " closures");
  AcceptanceScores s;
  s.closures = accepted.size();
  for (std::size_t k = 0; k < accepted.size(); ++k) {
    s.accepted += accepted[k] ? 1U : 0U;
    s.outliers += outlier[k] ? 1U : 0U;
    s.accepted_outliers += accepted[k] && outlier[k] ? 1U : 0U;
  }
  const std::size_t true_accepted = s.accepted - s.accepted_outliers;
  if (s.accepted > 0)
    s.precision = static_cast<double>(true_accepted) / static_cast<double>(s.accepted);
  if (s.closures > s.outliers)
    s.recall = static_cast<double>(true_accepted) / static_cast<double>(s.closures - s.outliers);
  return s;
}

}  // namespace antslam::slam
