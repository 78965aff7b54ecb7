// Pairwise consistent measurement set maximisation (Mangelson et al. 2018): the consistency graph
// of the loop closures (consistency.hpp), its maximum clique by branch and bound or by the ants
// (clique/), then least squares on the odometry and the clique's closures.

#include <stdexcept>
#include <string>

#include "clique/graph.hpp"
#include "robust_detail.hpp"
#include "slamgraph/consistency.hpp"

namespace antslam::slam {

CliqueReport maximum_consistent_set(const ConsistencyGraph& consistency, RobustMethod method,
                                    const RobustSettings& settings) {
  if (method != RobustMethod::pcm_exact && method != RobustMethod::pcm_aco)
    throw std::invalid_argument("maximum_consistent_set: " + std::string(to_string(method)) +
                                " is not a PCM method");
  const clique::Graph closures(consistency.closures, consistency.pairs);
  CliqueReport report;
  report.consistent_pairs = consistency.pairs.size();
  if (method == RobustMethod::pcm_exact) {
    const clique::ExactResult exact = clique::maximum_clique_exact(closures, settings.exact);
    report.clique = exact.clique;
    report.work = exact.nodes;
  } else {
    clique::AcoSearchSettings aco = settings.aco;
    aco.backend = settings.backend;
    aco.threads = settings.threads;
    const clique::AcoSearchResult ants = clique::maximum_clique_aco(closures, aco);
    report.clique = ants.clique;
    report.work = ants.iterations;
  }
  return report;
}

}  // namespace antslam::slam

namespace antslam::slam::detail {

void run_pcm(const PoseGraph& graph, const std::vector<Pose2>& initial,
             const RobustSettings& settings, RobustResult& result) {
  const std::size_t m = result.split.closures.size();
  result.accepted.assign(m, false);
  if (m > 0) {
    auto start = std::chrono::steady_clock::now();
    const ConsistencyGraph consistency = pairwise_consistency(
        graph, result.split, {settings.inlier_confidence, settings.backend, settings.threads});
    result.consistency_s = seconds_since(start);

    start = std::chrono::steady_clock::now();
    const CliqueReport report = maximum_consistent_set(consistency, result.method, settings);
    result.clique_s = seconds_since(start);
    for (const std::uint32_t k : report.clique.vertices) result.accepted[k] = true;
    result.clique = report;
  }
  std::vector<EdgeLoss> closure_loss(m);
  for (std::size_t k = 0; k < m; ++k)
    if (!result.accepted[k]) closure_loss[k] = {EdgeLoss::Kind::weighted, 0.0};
  optimize(graph, initial, edge_losses(graph, result.split, closure_loss), settings, result);
}

}  // namespace antslam::slam::detail
