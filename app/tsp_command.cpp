// antslam tsp: solve one TSPLIB instance, print a summary, optionally write the best tour, a
// per-iteration trace (CSV) and a JSON summary.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "antslam/aco/variant.hpp"
#include "antslam/dist/command_world.hpp"
#include "antslam/dist/communicator.hpp"
#include "antslam/dist/island_exchange.hpp"
#include "antslam/io/interrupts.hpp"
#include "antslam/io/json_output.hpp"
#include "antslam/io/output_files.hpp"
#include "antslam/io/progress.hpp"
#include "antslam/tsp/optima.hpp"
#include "antslam/tsp/run_io.hpp"
#include "antslam/tsp/tsplib.hpp"
#include "command_interrupts.hpp"
#include "commands.hpp"
#include "island_options.hpp"
#include "tsp_options.hpp"
#include "validators.hpp"

namespace antslam::cli {

namespace {

struct TspCommand {
  std::filesystem::path instance;
  TspOptions algorithm;
  IslandOptions islands;
  std::uint64_t iterations = 0;
  double time_s = 0.0;
  double cpu_time_s = 0.0;
  double optimum = 0.0;
  bool stop_at_optimum = false;
  bool quiet = false;  ///< print only "Best <length>" (ACOTSP's --quiet, read by irace's runners)
  std::size_t tries = 1;  ///< ACOTSP's independent tries; one run per call here
  std::filesystem::path tour_out;
  std::filesystem::path trace_csv;
  std::filesystem::path json_out;
};

std::string excess_text(double length, std::optional<double> optimum) {
  if (!optimum) return "";
  std::ostringstream out;
  out << std::showpos << std::fixed << std::setprecision(3) << 100.0 * (length / *optimum - 1.0)
      << "%";
  return out.str();
}

void print_islands(const aco::IslandSettings& s, const aco::IslandResult& r) {
  std::cout << "islands      " << s.colonies << " colonies (" << aco::to_string(s.topology)
            << ", exchange every " << s.exchange_every << " iterations; " << s.local
            << " per process), best from colony " << r.best_colony << ", " << r.exchanges
            << " exchanges, " << std::fixed << std::setprecision(3) << r.exchange_s
            << " s in the exchange (" << std::setprecision(1)
            << 100.0 * r.exchange_s / std::max(r.run.elapsed_s, 1e-9) << "% of the run)\n";
}

void print_summary(const TspCommand& c, const tsp::TspProblem& problem,
                   const tsp::SolverSettings& settings, const aco::RunResult& result, double length,
                   std::optional<double> optimum, double setup_s) {
  const tsp::Instance& instance = problem.instance();
  std::cout << "instance     " << instance.name() << " (" << instance.size() << " cities, "
            << tsp::to_string(instance.type()) << ")\n"
            << "algorithm    " << describe_algorithm(problem, c.algorithm, result.settings)
            << ", seed " << settings.aco.seed << ", " << result.settings.threads << " thread(s) ("
            << aco::to_string(result.settings.backend) << ")\n"
            << "best length  " << std::setprecision(15) << length;
  if (optimum)
    std::cout << "  (optimum " << *optimum << ", " << excess_text(length, optimum) << ")";
  std::cout << "\niterations   " << result.iterations
            << " (stopped: " << aco::to_string(result.reason) << ")\n"
            << std::fixed << std::setprecision(3) << "time         " << result.elapsed_s
            << " s, best found after " << result.time_to_best_s << " s (iteration "
            << result.best_iteration << ")\n"
            << "setup        " << setup_s
            << " s before the budget: reading the instance, candidate lists, the colony\n";
}

/// Writes the requested outputs; `interrupt_signal` non-zero: the run was stopped by that signal
/// and every output says it is partial (the tour's comment, a first comment line in the trace,
/// "interrupted" and "interrupt_signal" in the JSON).
void write_outputs(const TspCommand& c, io::OutputFiles& outputs, const tsp::TspProblem& problem,
                   const tsp::SolverSettings& settings, const aco::Termination& budget,
                   const aco::RunResult& result, double length, std::optional<double> optimum,
                   double setup_s, const std::vector<aco::IterationReport>& trace,
                   const std::optional<aco::IslandSettings>& islands,
                   const std::optional<aco::IslandResult>& island, int interrupt_signal) {
  const tsp::Instance& instance = problem.instance();
  const std::string partial = interrupt_signal != 0
                                  ? "partial: interrupted by " + io::signal_name(interrupt_signal) +
                                        " after iteration " + std::to_string(result.iterations)
                                  : "";
  if (!c.tour_out.empty())
    outputs.write(c.tour_out, [&](std::ostream& out) {
      std::ostringstream comment;
      comment << "length " << std::setprecision(15) << length << ", antslam tsp "
              << c.algorithm.variant << " seed " << settings.aco.seed;
      if (!partial.empty()) comment << ", " << partial;
      tsp::write_tour(out, instance.name() + ".tour", result.best.path, comment.str());
    });
  if (!c.trace_csv.empty())
    outputs.write(c.trace_csv, [&](std::ostream& out) {
      if (!partial.empty()) out << "# " << partial << '\n';
      tsp::write_trace_csv(out, trace);
    });
  if (!c.json_out.empty()) {
    nlohmann::json j =
        tsp::run_json(problem, settings, budget, result, length, optimum, setup_s, islands, island);
    j["interrupted"] = interrupt_signal != 0;
    if (interrupt_signal != 0) j["interrupt_signal"] = io::signal_name(interrupt_signal);
    outputs.write(c.json_out, io::json_text(j));
  }
  outputs.commit();
}

/// What an interrupted run kept, for its last line.
std::string kept_text(const TspCommand& c, const aco::RunResult& result, double length) {
  std::ostringstream kept;
  kept << "kept the best tour of " << result.iterations << " iterations (length "
       << std::setprecision(15) << length << ")";
  std::vector<std::string> files;
  for (const std::filesystem::path* f : {&c.tour_out, &c.trace_csv, &c.json_out})
    if (!f->empty()) files.push_back(f->string());
  for (std::size_t i = 0; i < files.size(); ++i)
    kept << (i == 0 ? ", written to " : ", ") << files[i];
  if (!files.empty()) kept << " (marked partial)";
  return kept.str();
}

void run(const TspCommand& c) {
  // An interrupt stops the run at the end of an iteration and the outputs keep what it found.
  // (Armed first: one during the set-up stops the work after its first iteration.)
  const CommandInterrupts interrupts;
  dist::Communicator& world = dist::command_world();
  const std::optional<aco::IslandSettings> islands = island_settings(c.islands, world, "tsp");
  const bool root = world.is_root();  // under MPI, rank 0 alone prints and writes
  const tsp::SolverSettings settings = solver_settings(c.algorithm);
  io::OutputFiles outputs;
  if (!c.tour_out.empty()) outputs.add(c.tour_out);
  if (!c.trace_csv.empty()) outputs.add(c.trace_csv);
  if (!c.json_out.empty()) outputs.add(c.json_out);
  const auto command_start = std::chrono::steady_clock::now();
  tsp::Instance read = tsp::read_instance(c.instance);
  require_tsp_memory(read.size(), c.algorithm, settings);
  const tsp::TspProblem problem(std::move(read), problem_settings(c.algorithm));
  const tsp::Instance& instance = problem.instance();
  const std::optional<double> optimum =
      c.optimum > 0.0 ? std::optional<double>(c.optimum) : tsp::known_optimum(c.instance);

  // The budgets count from the start of the search (Colony::run); reading the instance and
  // building the candidate lists and the colony come before it and are reported as setup.
  aco::Termination termination{
      .max_iterations = c.iterations, .time_limit_s = c.time_s, .cpu_time_limit_s = c.cpu_time_s};
  if (!termination.bounded()) {
    termination.time_limit_s = 10.0;
    if (!c.quiet && root)
      std::cout
          << "no budget given: stopping after 10 s (set --iterations, --time or --cpu-time)\n";
  }
  if (c.stop_at_optimum && optimum) termination.target_cost = *optimum;

  termination.stop = interrupts.token();

  io::Progress progress(!c.quiet && root && io::stderr_is_terminal());
  std::vector<aco::IterationReport> trace;
  const auto observer = [&](const aco::IterationReport& r) {
    if (!c.trace_csv.empty()) trace.push_back(r);
    if (!progress.enabled()) return;
    std::ostringstream line;
    line << instance.name() << "  iteration " << r.iteration << "  best " << r.global_best << ' '
         << excess_text(r.global_best, optimum) << "  " << std::fixed << std::setprecision(1)
         << r.elapsed_s << " s";
    progress.update(line.str());
  };
  std::optional<aco::IslandResult> island;
  if (islands)
    island = tsp::solve_islands(
        problem, settings, termination, *islands,
        world.size() > 1 ? dist::island_exchange(world) : aco::Exchange(aco::in_process_exchange),
        [&](const aco::IslandReport& r) { observer(r.run); });
  const aco::RunResult result =
      island ? island->run : tsp::solve(problem, settings, termination, observer);
  progress.clear();
  const int interrupt_signal = interrupts.signal();
  const double setup_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - command_start).count() -
      result.elapsed_s;

  const double length = instance.tour_length(result.best.path);
  if (length != result.best.cost)
    throw std::logic_error("internal error: the best tour's length does not match its cost");

  if (!root) return;
  if (c.quiet) {
    std::cout << "Best " << std::setprecision(15) << length << '\n';
  } else {
    print_summary(c, problem, settings, result, length, optimum, setup_s);
    if (island) print_islands(*islands, *island);
  }
  write_outputs(c, outputs, problem, settings, termination, result, length, optimum, setup_s, trace,
                islands, island, interrupt_signal);
  if (interrupt_signal != 0) throw io::Interrupted(interrupt_signal, kept_text(c, result, length));
}

}  // namespace

void add_tsp_command(CLI::App& app) {
  auto command = std::make_shared<TspCommand>();
  CLI::App* sub = app.add_subcommand("tsp", "Solve a TSPLIB instance with an ACO variant");
  sub->add_option("-i,--instance,--tsplibfile", command->instance, "TSPLIB .tsp file")->required();
  add_tsp_options(*sub, command->algorithm, true);
  add_island_options(*sub, command->islands);
  for (const aco::VariantInfo& info : aco::kVariants)  // ACOTSP's --as, --eas, ..., --mmas
    sub->add_flag_callback(
        "--" + std::string(info.name),
        [command, name = std::string(info.name)] { command->algorithm.variant = name; },
        "the same as --variant " + std::string(info.name));
  sub->add_flag("--quiet", command->quiet,
                "print one line, 'Best <length>', as ACOTSP's --quiet (for irace's runners)");
  sub->add_option("--tries", command->tries,
                  "ACOTSP's independent tries: 1 (one run per call; tsp-experiment repeats runs)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1}));
  sub->add_option("--iterations", command->iterations, "iteration budget (0: none)")
      ->check(non_negative_integer());
  sub->add_option("--time", command->time_s, "wall-clock budget in seconds (0: none)")
      ->check(finite_in(0.0, 1e9));
  sub->add_option("--cpu-time", command->cpu_time_s,
                  "process CPU-time budget in seconds, all threads (0: none)")
      ->check(finite_in(0.0, 1e9));
  sub->add_option("--optimum", command->optimum,
                  "known optimal length (default: optima.csv beside the instance)")
      ->check(finite_in(1e-300, 1e300));
  sub->add_flag("--stop-at-optimum", command->stop_at_optimum,
                "stop as soon as the known optimum is reached");
  sub->add_option("--tour-out", command->tour_out, "write the best tour (TSPLIB .tour)");
  sub->add_option("--trace-csv", command->trace_csv,
                  "write iteration,elapsed_s,iteration_best,global_best");
  sub->add_option("--json", command->json_out, "write a JSON summary of the run");
  sub->callback([command] { run(*command); });
}

}  // namespace antslam::cli
