// antslam tsp-experiment: instances x variants x thread counts x seeds under one budget; writes
// every run to a CSV file and a summary per (instance, variant, threads) as a Markdown table:
// best/mean/worst length, mean % over the optimum, runs that hit it, mean time to best. Under
// mpirun the runs are spread over the ranks and rank 0 writes.

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "antslam/aco/variant.hpp"
#include "antslam/dist/command_world.hpp"
#include "antslam/dist/farm.hpp"
#include "antslam/dist/result_bytes.hpp"
#include "antslam/io/interrupts.hpp"
#include "antslam/io/output_files.hpp"
#include "antslam/io/progress.hpp"
#include "antslam/tsp/experiment.hpp"
#include "antslam/tsp/tsplib.hpp"
#include "command_interrupts.hpp"
#include "commands.hpp"
#include "tsp_options.hpp"
#include "validators.hpp"

namespace antslam::cli {

namespace {

struct ExperimentCommand {
  std::vector<std::string> instances;
  std::filesystem::path data_dir = "data/tsplib";
  std::vector<std::string> variants = {"mmas"};
  std::vector<std::size_t> threads = {1};
  std::size_t seeds = 5;
  std::uint64_t first_seed = 1;
  TspOptions algorithm;
  std::uint64_t iterations = 0;
  double time_s = 0.0;
  double cpu_time_s = 0.0;
  bool stop_at_optimum = true;
  std::filesystem::path csv_out;
  std::filesystem::path markdown_out;
};

void run(const ExperimentCommand& c) {
  // An interrupt ends the run under way and keeps the finished ones.
  // (Armed first: one during the set-up stops the work after its first iteration.)
  const CommandInterrupts interrupts;
  tsp::ExperimentSettings e;
  for (const std::string& name : c.instances)
    e.instances.push_back(tsp::resolve_instance(name, c.data_dir));
  e.variants.clear();
  for (const std::string& name : c.variants) e.variants.push_back(*aco::parse_variant(name));
  e.threads = c.threads;
  e.seeds = c.seeds;
  e.first_seed = c.first_seed;
  e.problem = problem_settings(c.algorithm);
  e.solver = solver_settings(c.algorithm);
  e.termination = {
      .max_iterations = c.iterations, .time_limit_s = c.time_s, .cpu_time_limit_s = c.cpu_time_s};
  e.stop_at_optimum = c.stop_at_optimum;
  tsp::validate(e);
  // Every instance's colony must fit before the first run starts, not after hours of runs.
  for (const std::filesystem::path& path : e.instances) {
    const std::size_t cities = tsp::read_instance(path).size();
    for (const aco::Variant variant : e.variants) {
      tsp::SolverSettings solver = e.solver;
      solver.aco.variant = variant;
      require_tsp_memory(cities, c.algorithm, solver, path.filename().string());
    }
  }
  io::OutputFiles outputs;
  if (!c.csv_out.empty()) outputs.add(c.csv_out);
  if (!c.markdown_out.empty()) outputs.add(c.markdown_out);

  e.termination.stop = interrupts.token();

  io::Progress progress;
  const auto run_share = [&](std::span<const std::size_t> share) {
    e.only.emplace(share.begin(), share.end());
    return tsp::run_experiment(
        e, [&](std::size_t index, std::size_t total, const tsp::ExperimentRun& r,
               const aco::IterationReport& report) {
          std::ostringstream line;
          line << "run " << index + 1 << "/" << total << "  " << r.instance << ' '
               << aco::to_string(r.variant) << " t" << r.threads << " seed " << r.seed << "  best "
               << report.global_best << "  " << std::fixed << std::setprecision(1)
               << report.elapsed_s << " s";
          progress.update(line.str());
        });
  };
  // Run i on rank i % ranks (dist/farm.hpp); every run's seed depends on its index only.
  const std::vector<tsp::ExperimentRun> runs = dist::farm<tsp::ExperimentRun>(
      dist::command_world(), tsp::run_count(e), run_share,
      [](dist::ByteWriter& out, const tsp::ExperimentRun& r) { write(out, r); },
      dist::read_experiment_run);
  progress.clear();
  const int interrupt_signal = interrupts.signal();
  const std::string interruption =  // what an interrupted experiment's outputs say
      interrupt_signal == 0
          ? ""
          : "interrupted by " + io::signal_name(interrupt_signal) + " after " +
                std::to_string(runs.size()) + " of " + std::to_string(tsp::run_count(e)) + " runs";
  const std::string& ls = c.algorithm.local_search;
  tsp::write_summary_markdown(std::cout, runs, ls);
  if (!c.csv_out.empty())
    outputs.write(c.csv_out, [&](std::ostream& out) {
      if (!interruption.empty()) out << "# partial: " << interruption << '\n';
      tsp::write_runs_csv(out, runs, ls);
    });
  if (!c.markdown_out.empty())
    outputs.write(c.markdown_out, [&](std::ostream& out) {
      if (!interruption.empty()) out << "Partial: " << interruption << ".\n\n";
      tsp::write_summary_markdown(out, runs, ls);
    });
  outputs.commit();
  if (interrupt_signal != 0) {
    std::string kept = "kept the " + std::to_string(runs.size()) + " finished runs of " +
                       std::to_string(tsp::run_count(e));
    if (!c.csv_out.empty() || !c.markdown_out.empty()) kept += ", written marked partial";
    throw io::Interrupted(interrupt_signal, kept);
  }
}

}  // namespace

void add_tsp_experiment_command(CLI::App& app) {
  auto c = std::make_shared<ExperimentCommand>();
  CLI::App* sub = app.add_subcommand(
      "tsp-experiment", "Run instances x variants x threads x seeds; write CSV and Markdown");
  sub->add_option("--instances", c->instances,
                  "instance files, or names of <data-dir>/<name>.tsp (comma separated)")
      ->required()
      ->delimiter(',');
  sub->add_option("--data-dir", c->data_dir, "where instance names are looked up")
      ->capture_default_str();
  sub->add_option("--variants", c->variants, "ACO variants (comma separated)")
      ->delimiter(',')
      ->check(CLI::IsMember(aco::variant_names()))
      ->capture_default_str();
  sub->add_option("--threads", c->threads, "thread counts (comma separated)")
      ->delimiter(',')
      ->check(count_in(1, 1024))
      ->capture_default_str();
  sub->add_option("--seeds", c->seeds, "runs per configuration")
      ->check(count_in(1, 100000))
      ->capture_default_str();
  sub->add_option("--first-seed", c->first_seed, "seeds are first-seed, first-seed + 1, ...")
      ->check(non_negative_integer())
      ->capture_default_str();
  add_tsp_options(*sub, c->algorithm, false);
  sub->add_option("--iterations", c->iterations, "iteration budget per run (0: none)")
      ->check(non_negative_integer());
  sub->add_option("--time", c->time_s, "wall-clock budget per run in seconds (0: none)")
      ->check(finite_in(0.0, 1e9));
  sub->add_option("--cpu-time", c->cpu_time_s, "CPU-time budget per run in seconds (0: none)")
      ->check(finite_in(0.0, 1e9));
  sub->add_option("--stop-at-optimum", c->stop_at_optimum,
                  "end a run once it reaches the known optimum (as ACOTSP)")
      ->capture_default_str();
  sub->add_option("--csv", c->csv_out, "write every run (CSV)");
  sub->add_option("--markdown", c->markdown_out, "write the summary table (Markdown)");
  sub->callback([c] { run(*c); });
}

}  // namespace antslam::cli
