// Pairwise consistent measurement set maximisation (Mangelson et al. 2018): the consistency graph
// of the loop closures (consistency.hpp), its maximum clique by branch and bound or by the ants
// (clique/), then the joint check of the clique (robust.hpp, RobustSettings::check_clique) and
// least squares on the odometry and the closures that pass it.

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "antslam/clique/graph.hpp"
#include "antslam/clique/reduction.hpp"
#include "antslam/slamgraph/chi_square.hpp"
#include "antslam/slamgraph/consistency.hpp"
#include "antslam/slamgraph/shown_noise.hpp"
#include "robust_detail.hpp"

namespace antslam::slam {

double pairwise_confidence(double confidence, std::size_t closures) {
  return 1.0 - (1.0 - confidence) / static_cast<double>(std::max<std::size_t>(closures, 2) - 1);
}

CliqueReport maximum_consistent_set(const ConsistencyGraph& consistency, RobustMethod method,
                                    const RobustSettings& settings) {
  if (method != RobustMethod::pcm_exact && method != RobustMethod::pcm_aco)
    throw std::invalid_argument("maximum_consistent_set: " + std::string(to_string(method)) +
                                " is not a PCM method");
  const clique::Graph closures(consistency.closures, consistency.pairs);
  CliqueReport report;
  report.consistent_pairs = consistency.pairs.size();
  const auto search = [&](const clique::Graph& g) {
    if (method == RobustMethod::pcm_exact) {
      const clique::ExactResult exact = clique::maximum_clique_exact(g, settings.exact);
      report.work = exact.nodes;
      return exact.clique;
    }
    clique::AcoSearchSettings aco = settings.aco;
    aco.backend = settings.backend;
    aco.threads = settings.threads;
    const clique::AcoSearchResult ants = clique::maximum_clique_aco(g, aco);
    report.work = ants.iterations;
    return ants.clique;
  };
  // Below settings.prune_from closures the whole graph is searched: it takes seconds at most, and
  // the search then returns the clique it returned before the pruning existed (with the pruning
  // it may return another maximum clique of the same size, which moved 45 of 238 runs of the
  // published pcm-aco grid by one or two accepted closures; docs/notes/robust-closures-log.md).
  if (closures.size() < settings.prune_from) {
    report.searched = closures.size();
    report.clique = search(closures);
    return report;
  }
  // The search sees only the closures the pruning leaves (clique/reduction.hpp): on a graph whose
  // closures nearly all agree, a few hundred of thousands.
  const clique::CliqueReduction reduction = clique::reduce_for_maximum_clique(closures);
  report.searched = reduction.residual.size();
  report.clique = clique::maximum_clique_reduced(closures, reduction, search);
  return report;
}

std::optional<double> shown_variance_factor(const PoseGraph& graph, const ChainSplit& split,
                                            const std::vector<bool>& accepted_closures,
                                            std::span<const Pose2> poses, double c2) {
  if (accepted_closures.size() != split.closures.size() || poses.size() != graph.vertices.size())
    throw std::invalid_argument("shown_variance_factor: a flag per closure and a pose per vertex");
  const std::vector<double> chi2 = edge_chi2(graph, poses);
  std::vector<bool> closure(chi2.size(), false);
  std::vector<double> accepted;
  for (std::size_t k = 0; k < split.closures.size(); ++k) {
    closure[split.closures[k]] = true;
    if (accepted_closures[k]) accepted.push_back(chi2[split.closures[k]]);
  }
  double odometry_chi2 = 0.0;
  std::int64_t odometry_edges = 0;
  for (std::size_t e = 0; e < chi2.size(); ++e) {
    if (closure[e]) continue;
    odometry_chi2 += chi2[e];
    ++odometry_edges;
  }
  std::sort(accepted.begin(), accepted.end());
  std::vector<double> sum_below(accepted.size() + 1, 0.0);  // of the `kept` smallest
  for (std::size_t k = 0; k < accepted.size(); ++k) sum_below[k + 1] = sum_below[k] + accepted[k];
  const std::int64_t held = 3 * (static_cast<std::int64_t>(graph.vertices.size()) - 1);
  std::optional<double> f;
  for (std::size_t kept = accepted.size();;) {
    const std::int64_t dof = 3 * (odometry_edges + static_cast<std::int64_t>(kept)) - held;
    if (dof <= 0) return f;
    f = (odometry_chi2 + sum_below[kept]) / static_cast<double>(dof);
    const auto within = std::upper_bound(accepted.begin(), accepted.end(), *f * c2);
    const auto now = static_cast<std::size_t>(within - accepted.begin());
    if (now >= kept) return f;
    kept = now;  // fewer closures every round, so this ends
  }
}

}  // namespace antslam::slam

namespace antslam::slam::detail {

namespace {

/// The squared loss on the closures marked in `kept`; the others are left out.
std::vector<EdgeLoss> keep_only(const std::vector<bool>& kept) {
  std::vector<EdgeLoss> loss(kept.size());
  for (std::size_t k = 0; k < kept.size(); ++k)
    if (!kept[k]) loss[k] = {EdgeLoss::Kind::weighted, 0.0};
  return loss;
}

/// The consistency graph of `tested` (the graph, or the graph at another noise) by `tests` and
/// its maximum clique by the method of `result`, their times added to result's.
CliqueReport maximum_clique_of(const PoseGraph& tested, const ConsistencySettings& tests,
                               const RobustSettings& settings, RobustResult& result) {
  auto start = std::chrono::steady_clock::now();
  const ConsistencyGraph consistency = pairwise_consistency(tested, result.split, tests);
  result.consistency_s += seconds_since(start);
  start = std::chrono::steady_clock::now();
  CliqueReport report = maximum_consistent_set(consistency, result.method, settings);
  result.clique_s += seconds_since(start);
  return report;
}

/// The median squared distance of the unary cycles (a closure and the odometry between its
/// ends; CycleTest) of the closures marked in `closures`, none if there are none.
std::optional<double> median_unary_distance(const PoseGraph& graph, const ChainSplit& split,
                                            const ConsistencySettings& tests,
                                            const std::vector<bool>& closures) {
  const CycleTest test(graph, split, tests);
  std::vector<double> d2;
  for (std::size_t k = 0; k < closures.size(); ++k)
    if (closures[k]) d2.push_back(test.squared_distance(k));
  if (d2.empty()) return std::nullopt;
  const auto middle = d2.begin() + static_cast<std::ptrdiff_t>(d2.size() / 2);
  std::nth_element(d2.begin(), middle, d2.end());
  return *middle;
}

/// DCS on the `candidates` from result.poses (the other closures left out); accepted: the
/// candidates whose residual then passes chi2 <= c2 (`candidates` may be result.accepted).
void accept_after_dcs(const PoseGraph& graph, const std::vector<bool>& candidates, double c2,
                      double phi, const RobustSettings& settings, RobustResult& result) {
  std::vector<EdgeLoss> loss = keep_only(candidates);
  for (std::size_t k = 0; k < loss.size(); ++k)
    if (candidates[k]) loss[k] = {EdgeLoss::Kind::dcs, phi};
  optimize(graph, result.poses, edge_losses(graph, result.split, loss), settings, result);
  const std::vector<bool> within = closures_within(graph, result.split, result.poses, c2);
  for (std::size_t k = 0; k < within.size(); ++k) result.accepted[k] = candidates[k] && within[k];
}

/// The joint check of the clique: least squares on the clique (check_start_iterations
/// iterations: a start, not a solution), DCS on the clique's closures from there, and a clique
/// closure stays accepted when its residual passes the chi-square test. Pairwise tests over long
/// odometry spans have little power, so a clique can hold false closures that agree with every
/// other one pairwise but not with the map the others make together.
/// DCS's Phi: settings.dcs_phi (at the shown noise: c2, so that a closure within the test keeps
/// its full weight), or with check_phi > 0 that many times the clique's median unary distance
/// (robust.hpp); result.check_phi records it.
void check_clique(const PoseGraph& graph, const std::vector<Pose2>& initial, double c2,
                  const ConsistencySettings& tests, const RobustSettings& settings,
                  RobustResult& result) {
  RobustSettings start = settings;
  start.ceres.max_iterations = settings.check_start_iterations;
  optimize(graph, initial, edge_losses(graph, result.split, keep_only(result.accepted)), start,
           result);
  result.check_phi = settings.shown_noise ? c2 : settings.dcs_phi;
  if (settings.check_phi > 0.0) {
    const std::optional<double> median =
        median_unary_distance(graph, result.split, tests, result.accepted);
    if (median && *median > 0.0) result.check_phi = settings.check_phi * *median;
  }
  accept_after_dcs(graph, result.accepted, c2, *result.check_phi, settings, result);
}

/// The recalibrated check (robust.hpp): the noise the checked graph shows (its trimmed variance
/// factor f, above; unset when the checked graph has no redundancy or fits exactly), and when f
/// is below settings.recalibrate_below the core clique at the noise divided by f, least squares
/// on the closures of both cliques from the odometry, DCS on the closures of either from there,
/// and the test at chi2 <= f c2.
void recalibrated_check(const PoseGraph& graph, const std::vector<Pose2>& initial,
                        ConsistencySettings tests, double c2, const std::vector<bool>& clique,
                        const RobustSettings& settings, RobustResult& result) {
  const std::optional<double> f =
      shown_variance_factor(graph, result.split, result.accepted, result.poses, c2);
  if (!f || !(*f > 0.0) || !std::isfinite(*f)) return;
  result.variance_factor = f;
  if (!(*f < settings.recalibrate_below)) return;
  PoseGraph recalibrated = graph;
  for (PoseGraphEdge& e : recalibrated.edges) e.information /= *f;
  tests.linear_heading_sd *= std::sqrt(*f);  // the same deviation in the recalibrated units
  result.core = maximum_clique_of(recalibrated, tests, settings, result);

  std::vector<bool> both(clique.size(), false), either = clique;
  for (const std::uint32_t k : result.core->clique.vertices) {
    both[k] = clique[k];
    either[k] = true;
  }
  optimize(graph, initial, edge_losses(graph, result.split, keep_only(both)), settings, result);
  accept_after_dcs(graph, either, *f * c2, *result.check_phi, settings, result);
}

/// The selection at the noise `graph` states: the maximum clique, its joint check and the final
/// least squares. `tests` carries the confidence and the heading's linear regime.
void select_closures(const PoseGraph& graph, const std::vector<Pose2>& initial, double c2,
                     const ConsistencySettings& tests, const RobustSettings& settings,
                     RobustResult& result) {
  const std::size_t m = result.split.closures.size();
  result.accepted.assign(m, false);
  if (m > 0) {
    result.clique = maximum_clique_of(graph, tests, settings, result);
    for (const std::uint32_t k : result.clique->clique.vertices) result.accepted[k] = true;
  }
  const std::vector<bool> clique = result.accepted;
  if (settings.check_clique && m > 0) {
    check_clique(graph, initial, c2, tests, settings, result);
    recalibrated_check(graph, initial, tests, c2, clique, settings, result);
  }
  // Least squares on the accepted closures from the odometry and, after the check, from the
  // checked map: the check's solve can end in a wrong basin with right decisions, and under heavy
  // rotation noise the odometry start can too. The lower cost wins.
  const std::vector<EdgeLoss> accepted =
      edge_losses(graph, result.split, keep_only(result.accepted));
  if (!(settings.check_clique && m > 0)) {
    optimize(graph, initial, accepted, settings, result);
    return;
  }
  const std::vector<Pose2> checked = std::move(result.poses);
  const double from_odometry = optimize(graph, initial, accepted, settings, result);
  std::vector<Pose2> odometry_map = std::move(result.poses);
  const double from_checked = optimize(graph, checked, accepted, settings, result);
  if (!(from_checked < from_odometry)) result.poses = std::move(odometry_map);
}

}  // namespace

void run_pcm(const PoseGraph& stated, const std::vector<Pose2>& initial, double c2,
             const RobustSettings& settings, RobustResult& result) {
  const std::size_t m = result.split.closures.size();
  ConsistencySettings tests{.confidence = settings.inlier_confidence,
                            .backend = settings.backend,
                            .threads = settings.threads};
  // At the noise the graph shows (shown_noise.hpp) the tests are sharp, and a true closure must
  // pass all its m - 1 pairwise tests and the check: each at the family-wise confidence
  // (pairwise_confidence); that noise also says where a cycle's heading leaves the linear regime
  // (consistency.hpp). By default (widen_noise) only an axis the graph states narrower than its
  // short cycles show (by more than kWidenAbove) is decided at the noise they show, each test at
  // the inlier confidence; an axis stated wider is left to the recalibrated check.
  std::optional<PoseGraph> rescaled;
  if (settings.shown_noise || (settings.widen_noise && m > 0)) {
    const auto start = std::chrono::steady_clock::now();
    result.shown_noise = estimate_shown_noise(stated, result.split);
    NoiseScale scale = result.shown_noise->scale;
    if (settings.shown_noise) {
      tests.confidence = pairwise_confidence(settings.inlier_confidence, m);
      tests.linear_heading_sd = kLinearHeadingSd;
      c2 = chi_square3_quantile(tests.confidence);
    } else {
      const auto wider = [](double shown) { return shown > kWidenAbove ? shown : 1.0; };
      scale = {wider(scale.xy), wider(scale.theta)};
      if (scale.xy > 1.0 || scale.theta > 1.0) result.widened = scale;
    }
    if (settings.shown_noise || result.widened) rescaled = at_noise_scale(stated, scale);
    result.consistency_s += seconds_since(start);
  }
  select_closures(rescaled ? *rescaled : stated, initial, c2, tests, settings, result);
}

}  // namespace antslam::slam::detail
