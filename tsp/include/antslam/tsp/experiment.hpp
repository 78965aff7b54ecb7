#pragma once
// A TSP experiment: instances x variants x thread counts x seeds under one budget per run, and
// its reports: every run as CSV, and per (instance, variant, threads) a Markdown row with best,
// mean and worst length, mean % over the optimum, runs that reached it, mean time to best.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "antslam/aco/colony.hpp"
#include "antslam/aco/termination.hpp"
#include "antslam/aco/variant.hpp"
#include "antslam/tsp/problem.hpp"
#include "antslam/tsp/solver.hpp"

namespace antslam::tsp {

struct ExperimentSettings {
  std::vector<std::filesystem::path> instances;               ///< TSPLIB files
  std::vector<aco::Variant> variants = {aco::Variant::mmas};  ///< ACO variants
  std::vector<std::size_t> threads = {1};                     ///< thread counts building the ants
  std::size_t seeds = 5;         ///< runs per (instance, variant, threads)
  std::uint64_t first_seed = 1;  ///< seeds first_seed, first_seed + 1, ...
  ProblemSettings problem;       ///< candidate and neighbour lists
  SolverSettings solver;         ///< everything but the variant, seed and threads of a run
  aco::Termination termination;  ///< budget of every run (must be bounded)
  bool stop_at_optimum = true;   ///< end a run at the known optimum (as ACOTSP does)
  /// The runs to do (indices into the whole experiment's runs, results in this order), each
  /// exactly as in the whole experiment, so that processes can share it; all runs when empty.
  std::optional<std::vector<std::size_t>> only = std::nullopt;
};

/// How many runs the whole experiment has: instances x variants x threads x seeds.
std::size_t run_count(const ExperimentSettings& settings);

/// Throws std::invalid_argument naming the first nonsensical field (an unbounded budget, no
/// instance, variant, thread count or seed; the serial backend on more than one thread).
void validate(const ExperimentSettings& settings);

struct ExperimentRun {
  std::string instance;    ///< the instance's NAME
  std::size_t cities = 0;  ///< its size
  aco::Variant variant = aco::Variant::mmas;
  std::size_t threads = 1;        ///< threads that built the ants
  std::uint64_t seed = 0;         ///< the run's seed
  double length = 0.0;            ///< best tour length found
  std::optional<double> optimum;  ///< the instance's known optimum (optima.csv beside it)
  aco::RunResult result;          ///< iterations, times, stop reason, settings that ran

  /// 100 (length / optimum - 1), NaN without a known optimum.
  double excess_percent() const;
  /// The run reached the known optimum.
  bool hit_optimum() const { return optimum && length <= *optimum; }
};

/// Runs in progress: `index` of `total` in the whole experiment (0-based), the run's configuration
/// (no result yet) and the engine's report of its latest iteration.
using ExperimentObserver =
    std::function<void(std::size_t index, std::size_t total, const ExperimentRun& run,
                       const aco::IterationReport& report)>;

/// Every run (or those of settings.only), instance-major, then variant, threads and seed. Once
/// settings.termination.stop is requested, the runs finished until then (a run it cut short is
/// left out).
std::vector<ExperimentRun> run_experiment(const ExperimentSettings& settings,
                                          const ExperimentObserver& observer = {});

/// An instance by file, or by name in `data_dir` (`<data_dir>/<name>.tsp`); throws
/// std::runtime_error if neither exists.
std::filesystem::path resolve_instance(const std::string& name,
                                       const std::filesystem::path& data_dir);

/// One CSV row per run (header first); `local_search` names the local search in every row.
void write_runs_csv(std::ostream& out, std::span<const ExperimentRun> runs,
                    std::string_view local_search);

/// One Markdown table row per (instance, variant, threads), in the order of their first run.
void write_summary_markdown(std::ostream& out, std::span<const ExperimentRun> runs,
                            std::string_view local_search);

}  // namespace antslam::tsp
