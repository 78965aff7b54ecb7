// antslam robust: one robust back end on a g2o pose graph (slamgraph/robust.hpp); writes the
// optimised graph with the edges it kept, the accepted loop closures and a JSON report with
// precision and recall (when the false closures are known) and the ATE against references.

#include <CLI/CLI.hpp>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "antslam/aco/variant.hpp"
#include "antslam/eval/ate.hpp"
#include "antslam/io/errors.hpp"
#include "antslam/io/output_files.hpp"
#include "antslam/slamgraph/ceres_baseline.hpp"
#include "antslam/slamgraph/g2o.hpp"
#include "antslam/slamgraph/optimize.hpp"
#include "antslam/slamgraph/outliers.hpp"
#include "antslam/slamgraph/robust.hpp"
#include "antslam/slamgraph/robust_result_io.hpp"
#include "backend_option.hpp"
#include "commands.hpp"
#include "validators.hpp"

namespace antslam::cli {

namespace {

constexpr std::uint64_t kMaxIterations = 100'000'000;        ///< --iterations (count)
constexpr std::uint64_t kMaxProofNodes = 1'000'000'000'000;  ///< --proof-nodes (count)

struct RobustOptions {
  std::string input;
  std::string method = "pcm-aco";
  std::string output;
  std::vector<std::string> references;
  std::string outliers;
  std::string variant = "mmas";
  std::string backend = "auto";
  bool no_clique_check = false;
  bool shown_noise = false;
  bool no_widen = false;
  slam::RobustSettings s;
};

/// The false-closure list: --outliers, else GRAPH.outliers.txt beside the input if it exists.
std::optional<std::vector<bool>> outlier_flags(const RobustOptions& o, const slam::PoseGraph& graph,
                                               const slam::ChainSplit& split) {
  std::filesystem::path path = o.outliers;
  if (path.empty()) {
    path = slam::outliers_path_of(o.input);
    if (!std::filesystem::exists(path)) return std::nullopt;
  }
  return slam::read_outlier_flags(path, graph, split);
}

std::string outliers_file(const RobustOptions& o) {
  return o.outliers.empty() ? slam::outliers_path_of(o.input).string() : o.outliers;
}

void run(RobustOptions o) {
  const slam::RobustMethod method = *slam::parse_robust_method(o.method);  // checked at parse
  o.s.aco.parameters.variant = *aco::parse_variant(o.variant);             // time, both
  o.s.backend = parse_backend_option(o.backend);
  o.s.check_clique = !o.no_clique_check;
  o.s.shown_noise = o.shown_noise;
  o.s.widen_noise = !o.no_widen;
  aco::resolve(o.s.backend, o.s.threads);  // serial on more than one thread fails here, up front
  io::OutputFiles outputs;
  const std::filesystem::path graph_out = outputs.add(o.output + ".g2o");
  const std::filesystem::path accepted_out = outputs.add(o.output + ".accepted.txt");
  const std::filesystem::path json_out = outputs.add(o.output + ".json");

  // Everything is read and checked before anything is computed.
  const slam::PoseGraph graph = slam::read_g2o_file(o.input);
  const slam::ChainSplit split =
      io::in_context_of(o.input, [&] { return slam::split_sessions(graph, o.input); });
  const std::optional<std::vector<bool>> outlier =
      io::in_context_of(outliers_file(o), [&] { return outlier_flags(o, graph, split); });
  std::vector<std::vector<slam::Pose2>> reference_poses;
  for (const std::string& path : o.references) {
    reference_poses.push_back(slam::read_reference_poses(path));
    if (reference_poses.back().size() != graph.vertices.size())
      throw io::InputError(path + ": has " + std::to_string(reference_poses.back().size()) +
                           " poses, the graph " + std::to_string(graph.vertices.size()));
  }

  const slam::RobustResult r =
      io::in_context_of(o.input, [&] { return slam::solve_robust(graph, method, o.s, o.input); });

  std::optional<slam::AcceptanceScores> scores;
  if (outlier) scores = slam::score_acceptance(r.accepted, *outlier);
  slam::RobustRunInputs inputs{
      .graph = o.input, .outliers = outliers_file(o), .scores = scores, .references = {}};
  for (std::size_t i = 0; i < o.references.size(); ++i) {
    const eval::AteResult ate = eval::indexed_ate(r.poses, reference_poses[i]);
    inputs.references.push_back(
        {o.references[i], ate.translation_m.rmse, ate.translation_m.max, ate.rotation_deg.rmse});
  }

  const slam::PoseGraph kept = slam::kept_graph(graph, r);
  const slam::ResidualSummary fit = slam::residual_summary(kept, r.poses);
  outputs.write(graph_out, [&](std::ostream& out) { slam::write_g2o(out, kept); });
  outputs.write(accepted_out, [&](std::ostream& out) {
    for (std::size_t k = 0; k < split.closures.size(); ++k)
      if (r.accepted[k]) {
        const slam::PoseGraphEdge& e = graph.edges[split.closures[k]];
        out << e.from << ' ' << e.to << '\n';
      }
  });
  outputs.write(json_out, [&](std::ostream& out) {
    slam::write_robust_result(out, graph, o.s, r, fit, inputs);
  });
  outputs.commit();

  const auto accepted = std::count(r.accepted.begin(), r.accepted.end(), true);
  std::printf("%s on %s: %zu of %zu loop closures accepted", o.method.c_str(), o.input.c_str(),
              static_cast<std::size_t>(accepted), split.closures.size());
  if (scores)
    std::printf(" (%zu of %zu false ones; precision %.4f, recall %.4f)", scores->accepted_outliers,
                scores->outliers, scores->precision.value_or(1.0), scores->recall.value_or(1.0));
  std::printf("\n");
  for (const slam::ReferenceError& e : inputs.references)
    std::printf("  ATE against %s: %.4f m rms, %.4f m max\n", e.reference.c_str(), e.rmse_m,
                e.max_m);
  if (fit.variance_factor)
    std::printf(
        "  residuals of the kept graph: chi2 %.4g over %lld degrees of freedom "
        "(variance factor %.4g: 1 if the graph states its noise as it is)\n",
        fit.chi2, static_cast<long long>(fit.degrees_of_freedom), *fit.variance_factor);
  std::printf("  time %.3f s (consistency %.3f, clique %.3f, optimisation %.3f)\n", r.total_s,
              r.consistency_s, r.clique_s, r.optimize_s);
  std::printf("wrote %s.g2o, %s.accepted.txt, %s.json\n", o.output.c_str(), o.output.c_str(),
              o.output.c_str());
}

}  // namespace

void add_robust_command(CLI::App& app) {
  auto o = std::make_shared<RobustOptions>();
  CLI::App* cmd = app.add_subcommand(
      "robust", "Optimise a g2o pose graph whose loop closures may be false (robust back ends)");
  cmd->add_option("input", o->input, "g2o pose graph (VERTEX_SE2, EDGE_SE2)")->required();
  std::vector<std::string> methods;
  std::string help = "back end:";
  for (const slam::RobustMethodInfo& m : slam::kRobustMethods) {
    methods.emplace_back(m.name);
    help += " " + std::string(m.name) + " (" + std::string(m.summary) + ")";
  }
  cmd->add_option("--method", o->method, help)
      ->check(CLI::IsMember(methods))
      ->capture_default_str();
  cmd->add_option("-o,--output", o->output,
                  "prefix of PREFIX.g2o, PREFIX.accepted.txt and PREFIX.json")
      ->required();
  cmd->add_option("--reference", o->references,
                  "poses to compute the ATE against (.g2o, .tum or `x y theta` lines); repeatable");
  cmd->add_option("--outliers", o->outliers,
                  "the false closures, `i j` a line (default: GRAPH.outliers.txt if it exists)");
  cmd->add_option("--confidence", o->s.inlier_confidence,
                  "chi-square (3 dof) probability of the consistency and inlier tests")
      ->check(finite_in(1e-9, 1.0 - 1e-9))
      ->capture_default_str();
  cmd->add_option("--exact-time-limit", o->s.exact.time_limit_s,
                  "pcm-exact: branch-and-bound budget, s (0 = none)")
      ->check(finite_in(0.0, 1e9))
      ->capture_default_str();
  cmd->add_flag("--shown-noise", o->shown_noise,
                "pcm-*: decide at the noise the graph's short cycles show (x-y and heading "
                "scales of the stated covariances), every test at a family-wise confidence");
  cmd->add_flag("--no-clique-check", o->no_clique_check,
                "pcm-*: accept the clique as it is, without its joint check (the published PCM)");
  cmd->add_option("--check-phi", o->s.check_phi,
                  "pcm-*: Phi of the joint check's DCS in multiples of the clique closures' median "
                  "squared distance to their odometry (the noise the graph shows); 0 = DCS's Phi "
                  "at the stated noise")
      ->check(finite_in(0.0, 1e9))
      ->capture_default_str();
  cmd->add_option("--recalibrate-below", o->s.recalibrate_below,
                  "pcm-*: when the checked graph's variance factor f is below this, a second "
                  "clique at the noise it shows, DCS on both cliques' closures from the map of "
                  "those they share, and the test at that noise (0 = never, 1e9 = always)")
      ->check(finite_in(0.0, 1e9))
      ->capture_default_str();
  cmd->add_flag(
      "--no-widen", o->no_widen,
      "pcm-*: decide at the stated noise also where the graph's short cycles show more "
      "(by default an axis stated over 1.25 times narrower is widened to what they show)");
  cmd->add_option("--prune-from", o->s.prune_from,
                  "pcm-*: from this many closures the clique search sees only those the pruning "
                  "leaves (a greedy clique's size bounds the degree; closures that agree with all "
                  "others are kept without search)")
      ->check(non_negative_integer())
      ->capture_default_str();
  cmd->add_option("--variant", o->variant, "pcm-aco: ACO variant")
      ->check(CLI::IsMember(aco::variant_names()))
      ->capture_default_str();
  cmd->add_option("--ants", o->s.aco.parameters.ants, "pcm-aco: ants (0 = the variant's default)")
      ->check(count_in(0, slam::kMaxAnts))
      ->capture_default_str();
  cmd->add_option("--iterations", o->s.aco.termination.max_iterations,
                  "pcm-aco: iterations at most")
      ->check(count_in(1, kMaxIterations))
      ->capture_default_str();
  cmd->add_option("--plateau-steps", o->s.aco.plateau_steps,
                  "pcm-aco: plateau moves after each ant's (1,2)-swaps (0 = none)")
      ->check(count_in(0, kMaxIterations))
      ->capture_default_str();
  cmd->add_option("--proof-nodes", o->s.aco.proof_nodes,
                  "pcm-aco: then branch and bound from the ants' clique for at most this many "
                  "nodes: a proof that it is maximum, or a larger one (0 = none)")
      ->check(count_in(0, kMaxProofNodes))
      ->capture_default_str();
  cmd->add_option("--restart-stagnant", o->s.aco.parameters.restart_stagnant,
                  "pcm-aco, mmas: re-initialise the trails when the restart-best is this many "
                  "iterations old (0 = only on converged trails, as ACOTSP)")
      ->check(count_in(0, kMaxIterations))
      ->capture_default_str();
  cmd->add_option("--seed", o->s.aco.parameters.seed, "pcm-aco: seed of the ants")
      ->check(non_negative_integer())
      ->capture_default_str();
  cmd->add_option("--threads", o->s.threads,
                  "threads for the consistency pairs and the ants (0 = all cores)")
      ->check(count_in(0, kMaxThreads))
      ->capture_default_str();
  add_backend_option(*cmd, o->backend);
  cmd->callback([o] { run(*o); });
}

}  // namespace antslam::cli
