#include "antslam/mapping/report.hpp"

#include <cmath>
#include <vector>

#include "antslam/eval/report.hpp"
#include "antslam/frontend/report.hpp"
#include "antslam/slamgraph/refine.hpp"
#include "antslam/slamgraph/trials.hpp"

namespace antslam::mapping {

using frontend::gaussian_json;
using frontend::pose_json;
using nlohmann::json;

namespace {

json statistics_json(const slam::Statistics& s) {
  return {{"mean", s.mean}, {"std", s.std}, {"min", s.min}, {"max", s.max}};
}

json scores_json(const slam::Scores& s) { return {{"weight", s.weight}, {"chi2", s.chi2}}; }

json residual_json(const ClosureResidual& r) {
  return {{"residual", pose_json(r.residual)}, {"mahalanobis", r.mahalanobis}};
}

}  // namespace

json optimization_json(const slam::FragmentSet& set, const MappingSettings& settings,
                       const MappingResult& r) {
  const slam::OptimizeSettings& s = settings.optimize;
  std::vector<double> weights, chi2, seconds;
  json trials = json::array();
  for (std::size_t t = 0; t < r.trials.size(); ++t) {
    const slam::OptimizeResult& trial = r.trials[t];
    weights.push_back(trial.scores.weight);
    chi2.push_back(trial.scores.chi2);
    seconds.push_back(trial.elapsed_s);
    json entry = {{"trial", t},
                  {"seed", slam::trial_seed(s.seed, t)},
                  {"weight", trial.scores.weight},
                  {"chi2", trial.scores.chi2},
                  {"elapsed_s", trial.elapsed_s},
                  {"time_to_best_s", trial.time_to_best_s}};
    if (s.method == slam::Method::hybrid_nlopt)  // what the ants found before the refinement
      entry["aco_weight"] = slam::path_weight(set, trial.choice);
    trials.push_back(entry);
  }
  const slam::OptimizeResult& best = r.trials[r.best];
  const std::vector<slam::Pose2> map_alignments = slam::relative_alignments(r.frames);
  json alignments = json::array();
  for (std::size_t i = 0; i < map_alignments.size(); ++i) {
    const slam::Gaussian2& g = *set.fragments[i + 1].alignment;
    const Eigen::Vector3d d = g.residual(map_alignments[i]);
    const double m2 = d.dot(g.information() * d);
    alignments.push_back({{"fragment", i + 1},
                          {"pose", pose_json(map_alignments[i])},
                          {"mahalanobis", std::sqrt(m2)},
                          {"term", 1.0 - std::exp(-0.5 * m2)}});
  }
  json frames = json::array();
  for (const slam::Pose2& f : r.frames) frames.push_back(pose_json(f));
  json closing = {{"enabled", r.closing.has_value()}};
  if (r.closing) {
    json distrusted = json::array();
    for (std::size_t c = 0; c < set.closures.size(); ++c)
      if (!r.closing->trusted[c])
        distrusted.push_back({{"from", set.closures[c].from}, {"to", set.closures[c].to}});
    closing["selection"] = to_string(settings.closing.selection);
    if (r.closing->clique)
      closing["clique"] = {{"size", r.closing->clique->clique.vertices.size()},
                           {"upper_bound", r.closing->clique->clique.upper_bound},
                           {"optimal", r.closing->clique->clique.optimal},
                           {"consistent_pairs", r.closing->clique->consistent_pairs}};
    closing["solves"] = r.closing->solves;
    closing["distrusted"] = distrusted;
  }
  return {{"method", slam::to_string(s.method)},
          {"seed", s.seed},
          {"trials", r.trials.size()},
          {"iterations", s.iterations},
          {"ants", s.aco.ants},
          {"nlopt_algorithm", slam::to_string(s.refine.algorithm)},
          {"graduated_refinement", s.refine.graduated},
          {"scan_matcher", scores_json(r.scan_matcher)},
          {"best_trial", r.best},
          {"best", scores_json(best.scores)},
          {"closing", closing},
          {"map", scores_json(r.scores)},
          {"weight", statistics_json(slam::statistics(weights))},
          {"chi2", statistics_json(slam::statistics(chi2))},
          {"elapsed_s", statistics_json(slam::statistics(seconds))},
          {"per_trial", trials},
          {"frames", frames},
          {"alignments", alignments}};
}

json closures_json(const slam::FragmentSet& set, const MappingResult& r) {
  json out = json::array();
  for (std::size_t c = 0; c < set.closures.size(); ++c)
    out.push_back({{"from", set.closures[c].from},
                   {"to", set.closures[c].to},
                   {"anchor", pose_json(set.closures[c].anchor)},
                   {"hypothesis", gaussian_json(set.closures[c].hypothesis)},
                   {"scan_matcher", residual_json(r.before[c])},
                   {"optimized", residual_json(r.after[c])},
                   {"trusted", !r.closing || r.closing->trusted[c]},
                   {"within_2_sigma", r.after[c].mahalanobis <= kClosureSigmas}});
  return out;
}

json evaluation_json(const MapEvaluation& e) {
  return {{"reference", e.reference},
          {"scan_matcher", eval::to_json(e.scan_matcher)},
          {"optimized", eval::to_json(e.optimized)}};
}

json verdict_json(const slam::FragmentSet& set, const Verdict& v) {
  json outside = json::array();
  for (const std::size_t c : v.outside)
    outside.push_back({{"from", set.closures[c].from}, {"to", set.closures[c].to}});
  return {{"doubtful", v.doubtful},
          {"closures", v.closures},
          {"closures_outside_2_sigma", outside},
          {"largest_closure_mahalanobis", v.largest_closure},
          {"scans", v.scans},
          {"odometry_fallbacks", v.fallbacks},
          {"largest_alignment_mahalanobis", v.largest_alignment},
          {"largest_alignment_fragment", v.largest_alignment_fragment},
          {"line", v.line}};
}

json report_json(const std::string& log_path, const PipelineSettings& settings,
                 const PipelineResult& r) {
  const slam::FragmentSet& set = r.frontend.fragment_set;
  json report = frontend::input_json(log_path, r.log, settings.frontend, settings.map);
  report["frontend"] = frontend::result_json(r.frontend);
  report["optimization"] = optimization_json(set, settings.mapping, r.mapping);
  report["closures"] = closures_json(set, r.mapping);
  if (r.evaluation) report["evaluation"] = evaluation_json(*r.evaluation);
  if (r.maps) report["maps"] = {{"resolution_m", r.maps->resolution}};
  report["warnings"] = r.warnings;
  report["verdict"] = verdict_json(set, r.verdict);
  report["times"] = {{"read_s", r.times.read_s},
                     {"frontend_s", r.times.frontend_s},
                     {"scan_matching_s", r.frontend.stats.matching_seconds},
                     {"loop_closure_s", r.frontend.stats.closure_seconds},
                     {"optimization_s", r.times.optimization_s},
                     {"maps_s", r.times.maps_s},
                     {"total_s", r.times.total_s}};
  return report;
}

}  // namespace antslam::mapping
