// antslam tsp-experiment: instances x variants x thread counts x seeds under one budget; writes
// every run to a CSV file and a summary per (instance, variant, threads) as a Markdown table:
// best/mean/worst length, mean % over the optimum, runs that hit it, mean time to best.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "aco/variant.hpp"
#include "cli/atomic_file.hpp"
#include "cli/progress.hpp"
#include "commands.hpp"
#include "tsp/optima.hpp"
#include "tsp/tsplib.hpp"
#include "tsp_options_command.hpp"
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

struct Run {
  std::string instance;
  std::size_t cities = 0;
  std::string variant;
  std::size_t threads = 1;
  std::uint64_t seed = 0;
  double length = 0.0;
  std::optional<double> optimum;
  aco::RunResult result;
};

std::filesystem::path resolve(const ExperimentCommand& c, const std::string& name) {
  if (std::filesystem::is_regular_file(name)) return name;
  const std::filesystem::path path = c.data_dir / (name + ".tsp");
  if (!std::filesystem::is_regular_file(path))
    throw std::runtime_error("--instances: '" + name + "' is neither a file nor " + path.string());
  return path;
}

double excess(const Run& r) { return r.optimum ? 100.0 * (r.length / *r.optimum - 1.0) : NAN; }

void write_runs(std::ostream& out, const std::vector<Run>& runs, const std::string& ls) {
  out << "instance,cities,variant,local_search,threads,seed,best_length,optimum,excess_percent,"
         "hit_optimum,iterations,best_iteration,time_to_best_s,elapsed_s,stop_reason\n"
      << std::setprecision(10);
  for (const Run& r : runs)
    out << r.instance << ',' << r.cities << ',' << r.variant << ',' << ls << ',' << r.threads << ','
        << r.seed << ',' << r.length << ',' << (r.optimum ? *r.optimum : NAN) << ',' << excess(r)
        << ',' << (r.optimum && r.length <= *r.optimum ? 1 : 0) << ',' << r.result.iterations << ','
        << r.result.best_iteration << ',' << r.result.time_to_best_s << ',' << r.result.elapsed_s
        << ',' << aco::to_string(r.result.reason) << '\n';
}

/// One Markdown row per (instance, variant, threads), in the order first run.
void write_summary(std::ostream& out, const std::vector<Run>& runs, const std::string& ls) {
  out << "| instance | n | variant | local search | threads | runs | best | mean | worst | "
         "mean excess % | hit optimum | mean time to best (s) |\n"
      << "|---|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  std::vector<bool> done(runs.size(), false);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (done[i]) continue;
    std::vector<const Run*> group;
    for (std::size_t j = i; j < runs.size(); ++j)
      if (!done[j] && runs[j].instance == runs[i].instance && runs[j].variant == runs[i].variant &&
          runs[j].threads == runs[i].threads) {
        group.push_back(&runs[j]);
        done[j] = true;
      }
    double best = INFINITY, worst = 0.0, sum = 0.0, sum_excess = 0.0, sum_ttb = 0.0;
    int hits = 0;
    for (const Run* r : group) {
      best = std::min(best, r->length);
      worst = std::max(worst, r->length);
      sum += r->length;
      sum_excess += excess(*r);
      sum_ttb += r->result.time_to_best_s;
      hits += r->optimum && r->length <= *r->optimum ? 1 : 0;
    }
    const auto count = static_cast<double>(group.size());
    const Run& r = *group.front();
    out << "| " << r.instance << " | " << r.cities << " | " << r.variant << " | " << ls << " | "
        << r.threads << " | " << group.size() << " | " << std::fixed << std::setprecision(0) << best
        << " | " << std::setprecision(1) << sum / count << " | " << std::setprecision(0) << worst
        << " | ";
    if (r.optimum) {
      out << std::setprecision(3) << sum_excess / count << " | " << hits << "/" << group.size();
    } else {
      out << "- | -";
    }
    out << " | " << std::setprecision(2) << sum_ttb / count << " |\n";
  }
}

void run(const ExperimentCommand& c) {
  aco::Termination termination{
      .max_iterations = c.iterations, .time_limit_s = c.time_s, .cpu_time_limit_s = c.cpu_time_s};
  if (!termination.bounded())
    throw std::invalid_argument("set a budget: --iterations, --time or --cpu-time");
  TspOptions options = c.algorithm;
  std::vector<Run> runs;
  const std::size_t total = c.instances.size() * c.variants.size() * c.threads.size() * c.seeds;
  Progress progress;
  for (const std::string& name : c.instances) {
    const std::filesystem::path path = resolve(c, name);
    const tsp::TspProblem problem(tsp::read_instance(path), problem_settings(options));
    const std::optional<double> optimum = tsp::known_optimum(path);
    aco::Termination t = termination;
    if (c.stop_at_optimum && optimum) t.target_cost = *optimum;
    for (const std::string& variant : c.variants)
      for (const std::size_t threads : c.threads)
        for (std::uint64_t s = 0; s < c.seeds; ++s) {
          options.variant = variant;
          options.threads = threads;
          options.solver.aco.seed = c.first_seed + s;
          Run r{problem.instance().name(),
                problem.size(),
                variant,
                threads,
                options.solver.aco.seed,
                0.0,
                optimum,
                {}};
          std::ostringstream prefix;
          prefix << "run " << runs.size() + 1 << "/" << total << "  " << r.instance << ' '
                 << variant << " t" << threads << " seed " << r.seed;
          r.result = tsp::solve(
              problem, solver_settings(options), t, [&](const aco::IterationReport& report) {
                std::ostringstream line;
                line << prefix.str() << "  best " << report.global_best << "  " << std::fixed
                     << std::setprecision(1) << report.elapsed_s << " s";
                progress.update(line.str());
              });
          r.length = problem.instance().tour_length(r.result.best.path);
          runs.push_back(std::move(r));
        }
  }
  progress.clear();
  const std::string& ls = options.local_search;
  write_summary(std::cout, runs, ls);
  if (!c.csv_out.empty())
    write_atomically(c.csv_out, [&](std::ostream& out) { write_runs(out, runs, ls); });
  if (!c.markdown_out.empty())
    write_atomically(c.markdown_out, [&](std::ostream& out) { write_summary(out, runs, ls); });
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
      ->check(CLI::Range(std::size_t{1}, std::size_t{1024}))
      ->capture_default_str();
  sub->add_option("--seeds", c->seeds, "runs per configuration")
      ->check(CLI::Range(std::size_t{1}, std::size_t{100000}))
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
