#include "antslam/slamgraph/robust_result_io.hpp"
#include "antslam/version.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <ostream>

#include "antslam/aco/backend_kind.hpp"
#include "antslam/aco/variant.hpp"

namespace antslam::slam {

namespace {

using ordered_json = nlohmann::ordered_json;

ordered_json number_or_null(const std::optional<double>& v) {
  return v ? ordered_json(*v) : ordered_json(nullptr);
}

ordered_json settings_json(const RobustSettings& s) {
  return {{"inlier_confidence", s.inlier_confidence},
          {"cauchy_scale", s.cauchy_scale},
          {"dcs_phi", s.dcs_phi},
          {"shown_noise", s.shown_noise},
          {"check_clique", s.check_clique},
          {"check_phi", s.check_phi},
          {"recalibrate_below", s.recalibrate_below},
          {"widen_noise", s.widen_noise},
          {"prune_from", s.prune_from},
          {"gnc_mu_factor", s.gnc.mu_factor},
          {"exact_time_limit_s", s.exact.time_limit_s},
          {"aco_variant", aco::to_string(s.aco.parameters.variant)},
          {"aco_ants", s.aco.parameters.ants},
          {"aco_seed", s.aco.parameters.seed},
          {"aco_max_iterations", s.aco.termination.max_iterations},
          {"aco_stagnation_iterations", s.aco.termination.stagnation_iterations},
          {"aco_plateau_steps", s.aco.plateau_steps},
          {"aco_proof_nodes", s.aco.proof_nodes},
          {"aco_restart_stagnant", s.aco.parameters.restart_stagnant},
          {"backend", aco::to_string(s.backend)},
          {"threads", s.threads}};
}

}  // namespace

void write_robust_result(std::ostream& out, const PoseGraph& graph, const RobustSettings& s,
                         const RobustResult& r, const ResidualSummary& fit,
                         const RobustRunInputs& inputs) {
  ordered_json j = {{"format", kRobustResultFormat},
                    {"version", kRobustResultVersion},
                    {"antslam_version", kVersion},
                    {"input", inputs.graph},
                    {"method", to_string(r.method)},
                    {"vertices", graph.vertices.size()},
                    {"edges", graph.edges.size()},
                    {"closures", r.split.closures.size()},
                    {"accepted", std::count(r.accepted.begin(), r.accepted.end(), true)},
                    {"time_s",
                     {{"total", r.total_s},
                      {"consistency", r.consistency_s},
                      {"clique", r.clique_s},
                      {"optimize", r.optimize_s}}},
                    {"settings", settings_json(s)}};
  if (inputs.scores) {
    const AcceptanceScores& sc = *inputs.scores;
    j["outliers"] = {{"file", inputs.outliers},
                     {"count", sc.outliers},
                     {"accepted", sc.accepted_outliers},
                     {"precision", number_or_null(sc.precision)},
                     {"recall", number_or_null(sc.recall)}};
  }
  if (r.shown_noise) {
    j["shown_noise"] = {
        {"estimated", r.shown_noise->estimated},     {"scale_xy", r.shown_noise->scale.xy},
        {"scale_theta", r.shown_noise->scale.theta}, {"cycles", r.shown_noise->cycles},
        {"inliers", r.shown_noise->inliers},         {"rounds", r.shown_noise->rounds}};
  }
  if (r.widened) j["widened"] = {{"scale_xy", r.widened->xy}, {"scale_theta", r.widened->theta}};
  if (r.clique) {
    j["clique"] = {{"size", r.clique->clique.vertices.size()},
                   {"upper_bound", r.clique->clique.upper_bound},
                   {"optimal", r.clique->clique.optimal},
                   {"consistent_pairs", r.clique->consistent_pairs},
                   {"searched", r.clique->searched},
                   {"work", r.clique->work}};
  }
  if (r.check_phi) j["check"] = {{"dcs_phi", *r.check_phi}};
  if (r.variance_factor) {
    j["recalibration"] = {{"variance_factor", *r.variance_factor},
                          {"recalibrated", r.core.has_value()}};
    if (r.core) {
      j["recalibration"]["core_size"] = r.core->clique.vertices.size();
      j["recalibration"]["core_optimal"] = r.core->clique.optimal;
    }
  }
  if (r.method == RobustMethod::gnc) j["gnc_steps"] = r.gnc_steps;
  j["residuals"] = {{"chi2", fit.chi2},
                    {"degrees_of_freedom", fit.degrees_of_freedom},
                    {"variance_factor", number_or_null(fit.variance_factor)}};
  j["ate"] = ordered_json::array();
  for (const ReferenceError& e : inputs.references)
    j["ate"].push_back({{"reference", e.reference},
                        {"rmse_m", e.rmse_m},
                        {"max_m", e.max_m},
                        {"rotation_rmse_deg", e.rotation_rmse_deg}});
  out << j.dump(2) << '\n';
}

}  // namespace antslam::slam
