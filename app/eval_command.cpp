// `antslam eval EST REF`: scores an estimated trajectory against a reference, both in TUM format
// (docs/evaluation.md): ATE after rigid SE(2) alignment, RPE over a frame or distance step and,
// with --relations, the relations metric of Kuemmerle et al. 2009; with --fragment-set, the
// set's alignments and loop closures against the reference (precision and recall of the
// closures). Table on stdout, JSON on request.

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "antslam/eval/alignment.hpp"
#include "antslam/eval/fragment_set_check.hpp"
#include "antslam/eval/relations.hpp"
#include "antslam/eval/report.hpp"
#include "antslam/io/errors.hpp"
#include "antslam/io/json_output.hpp"
#include "antslam/io/output_files.hpp"
#include "antslam/slamgraph/fragment_set_io.hpp"
#include "antslam/slamgraph/trajectory.hpp"
#include "commands.hpp"
#include "validators.hpp"

namespace antslam::cli {

namespace {

struct EvalOptions {
  std::filesystem::path estimate;      ///< TUM file
  std::filesystem::path reference;     ///< TUM file
  std::filesystem::path relations;     ///< Kuemmerle relations file; empty = none
  std::filesystem::path fragment_set;  ///< fragment set to check; empty = none
  std::filesystem::path json;          ///< JSON result file; empty = none
  std::filesystem::path aligned;       ///< TUM file for the aligned estimate; empty = none
  eval::EvaluationSettings settings;   ///< tolerances (s), RPE step; align set from no_align
  bool no_align = false;               ///< --no-align given
  std::optional<double> rpe_distance;  ///< --rpe-distance, metres, if given
};

slam::Trajectory read_trajectory(const std::filesystem::path& path) {
  slam::Trajectory trajectory = slam::read_tum_file(path);
  if (trajectory.empty()) throw std::runtime_error(path.string() + ": no poses");
  return trajectory;
}

void run_eval(EvalOptions options) {
  options.settings.align = !options.no_align;
  if (options.rpe_distance) options.settings.rpe.metres = *options.rpe_distance;
  io::OutputFiles outputs;
  if (!options.aligned.empty()) outputs.add(options.aligned);
  if (!options.json.empty()) outputs.add(options.json);
  const slam::Trajectory estimate = read_trajectory(options.estimate);
  const slam::Trajectory reference = read_trajectory(options.reference);
  std::vector<eval::Relation> relations;
  if (!options.relations.empty()) relations = eval::read_relations_file(options.relations);

  const eval::Evaluation evaluation = io::in_context_of(
      {options.estimate, options.reference, options.relations},
      [&] { return eval::evaluate(estimate, reference, options.settings, relations); });

  std::optional<eval::FragmentSetCheck> check;
  if (!options.fragment_set.empty()) {
    eval::FragmentSetCheckSettings settings;
    settings.max_dt = options.settings.max_dt;
    check = eval::check_fragment_set(slam::read_fragment_set_file(options.fragment_set), reference,
                                     settings);
  }
  if (!options.aligned.empty()) {
    const slam::Trajectory aligned = eval::transformed(estimate, evaluation.ate.alignment);
    outputs.write(options.aligned, [&](std::ostream& out) { slam::write_tum(out, aligned); });
  }
  if (!options.json.empty()) {
    nlohmann::json json = eval::to_json(evaluation);
    json["estimate"] = options.estimate.string();
    json["reference"] = options.reference.string();
    if (!options.relations.empty()) json["relations"]["file"] = options.relations.string();
    if (check) {
      json["fragment_set"] = eval::to_json(*check);
      json["fragment_set"]["file"] = options.fragment_set.string();
    }
    outputs.write(options.json, io::json_text(json));
  }
  outputs.commit();
  eval::print_table(std::cout, evaluation);
  if (check) {
    const auto percent = [](const std::optional<double>& v) {
      return v ? std::to_string(static_cast<int>(std::lround(100.0 * *v))) + " %" : "-";
    };
    std::cout << "loop closures: " << check->correct_closures << " of " << check->checked_closures
              << " correct (precision " << percent(check->precision()) << "), "
              << check->revisits_closed << " of " << check->revisits
              << " revisiting fragments closed (recall " << percent(check->recall()) << ")\n";
  }
}

}  // namespace

void add_eval_command(CLI::App& app) {
  auto options = std::make_shared<EvalOptions>();
  CLI::App* cmd = app.add_subcommand(
      "eval", "Score an estimated trajectory against a reference (TUM files): ATE, RPE, relations");
  cmd->add_option("EST", options->estimate, "estimated trajectory, TUM format")->required();
  cmd->add_option("REF", options->reference, "reference trajectory, TUM format")->required();
  cmd->add_option("--max-dt", options->settings.max_dt,
                  "association tolerance between timestamps, seconds")
      ->capture_default_str()
      ->check(finite_at_least_zero());
  cmd->add_flag("--no-align", options->no_align,
                "score the estimate as it is, without rigid SE(2) alignment");
  auto* frames =
      cmd->add_option("--rpe-frames", options->settings.rpe.frames, "RPE step in associated poses")
          ->capture_default_str()
          ->check(count_in(1, 1'000'000'000));
  cmd->add_option("--rpe-distance", options->rpe_distance,
                  "RPE step as distance travelled along the reference, metres")
      ->check(finite_positive())
      ->excludes(frames);
  cmd->add_option("--relations", options->relations,
                  "Kuemmerle et al. 2009 relations file (t1 t2 dx dy dz droll dpitch dyaw)");
  cmd->add_option("--relations-max-dt", options->settings.relations_max_dt,
                  "tolerance between relation and estimate timestamps, seconds")
      ->capture_default_str()
      ->check(finite_at_least_zero());
  cmd->add_option("--fragment-set", options->fragment_set,
                  "fragment set (JSON) whose alignments and loop closures to check against REF");
  cmd->add_option("--json", options->json, "write the results as JSON to this file");
  cmd->add_option("--aligned-out", options->aligned,
                  "write the estimate moved by the ATE alignment to this TUM file");
  cmd->callback([options] { run_eval(*options); });
}

}  // namespace antslam::cli
