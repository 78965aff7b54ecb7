#include "antslam/mapping/close_loops.hpp"

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include "antslam/slamgraph/name_table.hpp"

namespace antslam::mapping {

std::string_view to_string(ClosureSelection selection) {
  return slam::detail::name_in(kClosureSelections, selection);
}

std::optional<ClosureSelection> parse_closure_selection(std::string_view name) {
  return slam::detail::value_in(kClosureSelections, name);
}

namespace {

/// Least squares over the alignments and the trusted closures (the alignments' means' chain if
/// none is trusted).
std::vector<slam::Pose2> solve_trusted(const slam::FragmentSet& set,
                                       std::span<const slam::Pose2> initial,
                                       const std::vector<bool>& trusted,
                                       const ClosingSettings& settings, Closing& out) {
  slam::FragmentSet subset = set;
  subset.closures.clear();
  for (std::size_t c = 0; c < set.closures.size(); ++c)
    if (trusted[c]) subset.closures.push_back(set.closures[c]);
  if (subset.closures.empty()) return slam::chain(slam::mean_alignments(set));
  ++out.solves;
  return slam::optimize_with_ceres(subset, initial, false, settings.ceres).frames;
}

/// PCM: the maximum clique of the pairwise consistency graph.
Closing consistent_set(const slam::FragmentSet& set, const ClosingSettings& settings) {
  const slam::RobustSettings& pcm = settings.pcm;
  const slam::ConsistencyGraph consistency = slam::pairwise_consistency(
      set, {.confidence = pcm.inlier_confidence, .backend = pcm.backend, .threads = pcm.threads});
  const slam::RobustMethod method = settings.selection == ClosureSelection::pcm_exact
                                        ? slam::RobustMethod::pcm_exact
                                        : slam::RobustMethod::pcm_aco;
  Closing out;
  out.clique = slam::maximum_consistent_set(consistency, method, pcm);
  out.trusted.assign(set.closures.size(), false);
  for (const std::uint32_t c : out.clique->clique.vertices) out.trusted[c] = true;
  return out;
}

}  // namespace

void validate(const ClosingSettings& s) {
  if (!(s.outlier_chi2 > 0.0) || !std::isfinite(s.outlier_chi2))
    throw std::invalid_argument("closing: outlier_chi2 must be a positive number");
  if (s.ceres.max_iterations <= 0)
    throw std::invalid_argument("closing: ceres.max_iterations must be positive");
}

Closing close_loops(const slam::FragmentSet& set, std::span<const slam::Pose2> start,
                    const ClosingSettings& settings) {
  validate(settings);
  if (start.size() != set.fragments.size())
    throw std::invalid_argument("closing: got " + std::to_string(start.size()) +
                                " frames, expected " + std::to_string(set.fragments.size()));
  const std::vector<slam::Pose2> initial = slam::relative_alignments(start);
  Closing out;
  if (settings.selection == ClosureSelection::iterative_chi2) {
    out.trusted.assign(set.closures.size(), true);
  } else {
    out = consistent_set(set, settings);
    if (!settings.pcm.check_clique) {
      out.frames = solve_trusted(set, initial, out.trusted, settings, out);
      return out;
    }
  }
  for (;;) {
    out.frames = solve_trusted(set, initial, out.trusted, settings, out);
    // The trusted closure that agrees worst with the joint solution.
    double worst = 0.0;
    std::size_t worst_index = 0;
    for (std::size_t c = 0; c < set.closures.size(); ++c) {
      if (!out.trusted[c]) continue;
      const slam::LoopClosure& closure = set.closures[c];
      const double m2 =
          closure.hypothesis.mahalanobis_squared(slam::closure_pose(closure, out.frames));
      if (m2 > worst) {
        worst = m2;
        worst_index = c;
      }
    }
    if (worst <= settings.outlier_chi2) return out;  // also when none is trusted (worst = 0)
    out.trusted[worst_index] = false;
  }
}

}  // namespace antslam::mapping
