// antslam optimize: run one optimizer variant on a fragment set or a pose graph (g2o, TORO), many
// trials in parallel; write the result JSON, a per-trial CSV and a convergence CSV.

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "antslam/dist/command_world.hpp"
#include "antslam/dist/communicator.hpp"
#include "antslam/dist/farm.hpp"
#include "antslam/dist/island_exchange.hpp"
#include "antslam/dist/result_bytes.hpp"
#include "antslam/eval/evaluation.hpp"
#include "antslam/io/errors.hpp"
#include "antslam/io/interrupts.hpp"
#include "antslam/io/memory.hpp"
#include "antslam/io/output_files.hpp"
#include "antslam/io/progress.hpp"
#include "antslam/slamgraph/fragment_set_io.hpp"
#include "antslam/slamgraph/g2o.hpp"
#include "antslam/slamgraph/graph_optimize.hpp"
#include "antslam/slamgraph/result_io.hpp"
#include "antslam/slamgraph/study_input.hpp"
#include "antslam/slamgraph/trials.hpp"
#include "command_interrupts.hpp"
#include "commands.hpp"
#include "island_options.hpp"
#include "optimizer_options.hpp"
#include "validators.hpp"

namespace antslam::cli {

namespace {

struct OptimizeOptions {
  std::string input;
  OptimizerOptions optimizer;
  std::string output;
  std::string reference;
  std::string g2o_out;
  std::string tum_out;
  std::size_t trials = 1;
  std::size_t threads = 1;
  slam::G2oImportSettings import;
  IslandOptions islands;
  slam::OptimizeSettings s;  ///< resolved from `optimizer`
};

/// The input as it is (without its reference); a pose graph whose fragment chain, if the method
/// needs one, is refused up front when its -m samples would not fit in memory.
slam::StudyInput read_input(const OptimizeOptions& o) {
  slam::StudyInput input = slam::read_study_input(o.input);
  if (input.graph && slam::needs_fragment_chain(o.s.method))
    io::require_memory("-m " + std::to_string(o.import.samples) + " (the samples)",
                       slam::fragment_set_bytes(input.graph->vertices.size(), o.import.samples, 0));
  return input;
}

/// The trials of `share` (indices of the study's trials), with their progress on a terminal
/// (cleared before the summary).
std::vector<slam::OptimizeResult> run_share(const slam::StudyInput& input, const OptimizeOptions& o,
                                            std::span<const std::size_t> share) {
  io::Progress progress;
  const slam::TrialsObserver finished = [&](std::size_t done) {
    if (o.trials > 1)
      progress.update(
          "trials finished: " + std::to_string(done) + "/" + std::to_string(share.size()),
          done == share.size());
  };
  const slam::OptimizeObserver convergence = [&](const slam::ConvergencePoint& p) {
    char line[128];
    std::snprintf(line, sizeof line, "iteration %llu  best weight %.6f  %.2f s",
                  static_cast<unsigned long long>(p.iteration), p.best_weight, p.elapsed_s);
    progress.update(line);
  };
  const slam::TrialSettings trials{o.trials, o.threads, o.s.backend,
                                   std::vector<std::size_t>(share.begin(), share.end())};
  return slam::run_trials(input, o.s, o.import, trials, finished, convergence);
}

/// Every trial of the study, farmed over the command's processes (dist/farm.hpp); the one trial
/// of an island run runs on every process instead, each with its colonies, and every process
/// receives its result (aco/islands.hpp).
std::vector<slam::OptimizeResult> run_study(const slam::StudyInput& input,
                                            const OptimizeOptions& o) {
  if (o.s.islands) {
    const std::size_t first_trial = 0;
    return io::in_context_of(o.input, [&] { return run_share(input, o, {&first_trial, 1}); });
  }
  return dist::farm<slam::OptimizeResult>(
      dist::command_world(), o.trials,
      [&](std::span<const std::size_t> share) {
        return io::in_context_of(o.input, [&] { return run_share(input, o, share); });
      },
      [](dist::ByteWriter& out, const slam::OptimizeResult& r) { write(out, r); },
      dist::read_optimize_result);
}

void print_summary(const slam::StudyResult& r, const slam::StudyInput& input,
                   const OptimizeOptions& o) {
  const std::size_t ranks = dist::command_world().size();
  const std::string on_ranks = ranks == 1 ? "" : std::to_string(ranks) + " ranks x ";
  std::printf("%s on %s (%s): %zu trial%s on %s%zu thread%s\n",
              std::string(slam::to_string(r.method)).c_str(), o.input.c_str(),
              input.size_text().c_str(), r.trials, r.trials == 1 ? "" : "s", on_ranks.c_str(),
              o.threads, o.threads == 1 ? "" : "s");
  std::printf("  weight (eq. 10)  %.6f +- %.6f  (best %.6f, worst %.6f)\n", r.weight.mean,
              r.weight.std, r.weight.min, r.weight.max);
  std::printf("  chi2             %.6g +- %.6g  (best trial %.6g)\n", r.chi2.mean, r.chi2.std,
              r.best.scores.chi2);
  std::printf("  time per trial   %.3f ms +- %.3f ms\n", 1e3 * r.elapsed_s.mean,
              1e3 * r.elapsed_s.std);
  if (r.error)
    std::printf("  error vs reference (best trial)  ATE %.4f m rms, %.4f m max, %.3f deg rms\n",
                r.error->rmse_m, r.error->max_m, r.error->rmse_deg);
}

void run(const OptimizeOptions& options) {
  // An interrupt stops the study, which keeps its finished trials (one trial: what it found).
  // (Armed first: one during the set-up stops the work after its first iteration.)
  const CommandInterrupts interrupts;
  OptimizeOptions o = options;
  o.s = optimize_settings(o.optimizer);
  dist::Communicator& world = dist::command_world();
  if (o.islands.colonies > 0) {  // without --colonies, ranks share the trials
    if (o.trials != 1)
      throw io::UsageError("--colonies runs one trial of " + std::to_string(o.islands.colonies) +
                           " colonies: give --trials 1, not " + std::to_string(o.trials));
    o.s.islands = island_settings(o.islands, world, "optimize");
    if (o.s.islands && world.size() > 1) o.s.exchange = dist::island_exchange(world);
  }
  slam::validate(o.s);
  if (o.threads == 0) o.threads = std::max(1U, std::thread::hardware_concurrency());
  const std::string prefix =
      o.output.empty() ? std::filesystem::path(o.input).stem().string() + "." + o.optimizer.method
                       : o.output;
  io::OutputFiles outputs;
  const std::filesystem::path result_json = outputs.add(prefix + ".json");
  const std::filesystem::path trials_csv = outputs.add(prefix + ".trials.csv");
  const std::filesystem::path convergence_csv = outputs.add(prefix + ".convergence.csv");
  const std::filesystem::path times_json = outputs.add(prefix + ".times.json");
  if (!o.g2o_out.empty()) outputs.add(o.g2o_out);
  if (!o.tum_out.empty()) outputs.add(o.tum_out);

  slam::StudyInput input = io::in_context_of(o.input, [&] { return read_input(o); });
  slam::read_study_reference(input, o.reference);
  io::require_memory("--trials " + std::to_string(o.trials) + " (the trials' results)",
                     static_cast<double>(o.trials) * slam::trial_result_bytes(input.poses()));
  o.s.stop = interrupts.token();
  const std::vector<slam::OptimizeResult> trials = run_study(input, o);
  const int interrupt_signal = interrupts.signal();
  if (interrupt_signal != 0 && trials.empty())
    throw io::Interrupted(interrupt_signal, "no trial had finished; nothing written");
  slam::StudyResult r = slam::summarize(o.input, o.s, trials);
  if (interrupt_signal != 0)
    r.interrupted = slam::StudyInterruption{io::signal_name(interrupt_signal), o.trials};
  if (!input.reference.empty()) r.error = eval::frames_error(r.best.frames, input.reference);
  if (!world.is_root()) return;  // the colonies' ranks: rank 0 alone writes and prints

  std::string partial;  // the first line of the CSV files of an interrupted study
  if (r.interrupted)
    partial = "# partial: interrupted by " + r.interrupted->signal +
              (o.trials == 1 ? std::string(": the trial's best so far")
                             : " after " + std::to_string(trials.size()) + " of " +
                                   std::to_string(o.trials) + " trials") +
              "\n";
  outputs.write(result_json, [&](std::ostream& out) { slam::write_result(out, r); });
  outputs.write(trials_csv, [&](std::ostream& out) {
    out << partial;
    slam::write_trials_csv(out, trials, o.s.seed);
  });
  outputs.write(convergence_csv, [&](std::ostream& out) {
    out << partial;
    slam::write_convergence_csv(out, trials);
  });
  outputs.write(times_json, [&](std::ostream& out) { slam::write_times_json(out, trials); });
  if (!o.g2o_out.empty())
    outputs.write(o.g2o_out, [&](std::ostream& out) {
      slam::write_pose_graph(out, input.map_graph(r.best.frames), o.g2o_out);
    });
  if (!o.tum_out.empty())
    outputs.write(o.tum_out, [&](std::ostream& out) {
      slam::write_tum(out, input.trajectory(r.best.frames));
    });
  outputs.commit();

  print_summary(r, input, o);
  std::printf("wrote %s.json, %s.trials.csv, %s.convergence.csv, %s.times.json\n", prefix.c_str(),
              prefix.c_str(), prefix.c_str(), prefix.c_str());
  if (!o.g2o_out.empty()) std::printf("wrote %s\n", o.g2o_out.c_str());
  if (!o.tum_out.empty()) std::printf("wrote %s\n", o.tum_out.c_str());
  if (r.interrupted) {
    throw io::Interrupted(
        interrupt_signal,
        (o.trials == 1 ? std::string("kept the trial's best so far")
                       : "kept trials 0-" + std::to_string(trials.size() - 1) + " of " +
                             std::to_string(o.trials) + " (finished before the stop)") +
            ", written marked partial");
  }
}

}  // namespace

void add_optimize_command(CLI::App& app) {
  auto o = std::make_shared<OptimizeOptions>();
  CLI::App* cmd = app.add_subcommand("optimize", "Run an optimizer on a fragment set");
  cmd->add_option(
         "input", o->input,
         "fragment-set JSON, or a pose graph (.g2o, .graph): ceres, ceres-robust and nlopt "
         "run on the graph from its vertex poses, the other methods on its fragment chain")
      ->required();
  cmd->add_option("--trials", o->trials,
                  "independent trials (trial t: seed mix(seed, t)); under mpirun, trial t runs on "
                  "rank t % ranks")
      ->check(count_in(1, kMaxTrials))
      ->capture_default_str();
  cmd->add_option("--threads", o->threads,
                  "threads (of each rank under mpirun): trials run in parallel (with --trials 1: "
                  "the ants); 0 = all cores")
      ->check(count_in(0, kMaxThreads))
      ->capture_default_str();
  add_optimizer_options(*cmd, o->optimizer);
  add_island_options(*cmd, o->islands);
  cmd->add_option("-m,--samples", o->import.samples,
                  "pose graph input: samples drawn per alignment")
      ->check(count_in(1, kMaxSamples))
      ->capture_default_str();
  cmd->add_option("--reference", o->reference,
                  "ground-truth poses (.g2o, .graph, .tum, `x y theta` lines) for the trajectory "
                  "error");
  cmd->add_option("-o,--output", o->output,
                  "output prefix (default: <input stem>.<method>): PREFIX.json, "
                  "PREFIX.trials.csv, PREFIX.convergence.csv (the same for a seed on any thread "
                  "count or backend), PREFIX.times.json (wall-clock times)");
  cmd->add_option("--g2o-out", o->g2o_out,
                  "write the best map as a pose graph (a .graph name: TORO lines)");
  cmd->add_option("--tum-out", o->tum_out, "write the best map's trajectory in TUM format");
  cmd->callback([o] {
    o->import.seed = o->optimizer.settings.seed;
    run(*o);
  });
}

}  // namespace antslam::cli
