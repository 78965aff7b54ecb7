#pragma once
// Options shared by `antslam tsp` and `antslam tsp-experiment`: the ACO variant and its
// parameters, local search, candidate lists, focused construction, backend and threads. Where
// an option means the same as one of ACOTSP 1.03 (Stuetzle), ACOTSP's name is accepted too
// (--nnls, --nnants, --localsearch, --dlb, --rasranks, --elitistants), so that tuning scenarios
// written for ACOTSP (irace's acotsp example) can call antslam.

#include <CLI/CLI.hpp>

#include <cstddef>
#include <string>

#include "antslam/aco/colony.hpp"
#include "antslam/tsp/problem.hpp"
#include "antslam/tsp/solver.hpp"

namespace antslam::cli {

struct TspOptions {
  std::string variant = "mmas";       ///< as, eas, ras, acs, mmas, hybrid
  std::string local_search = "3opt";  ///< none, 2opt, 2.5opt, 3opt
  std::string ls_start = "changed";  ///< changed: queue cities whose edges changed; all: every city
  std::string backend = "auto";      ///< aco::kBackends: auto, serial, omp, tbb
  std::size_t threads = 1;           ///< threads building ants
  tsp::ProblemSettings problem;      ///< candidate and neighbour lists, matrix limit
  tsp::SolverSettings solver;        ///< engine parameters (variant/local search set from names)
};

/// Registers the options on `command`; values land in `options`. Without `single_run`,
/// --variant, --seed and --threads are left to the caller (experiments sweep them).
void add_tsp_options(CLI::App& command, TspOptions& options, bool single_run);

/// ACOTSP's --localsearch level ("0".."3") as our name ("none", "2opt", "2.5opt", "3opt").
std::string acotsp_local_search(const std::string& level);

/// Checks the names and fills options.solver's variant, local search, backend and threads;
/// throws std::invalid_argument naming the option on a bad value.
tsp::SolverSettings solver_settings(const TspOptions& options);
tsp::ProblemSettings problem_settings(const TspOptions& options);

/// Refuses up front (require_memory: UsageError) a run on `cities` cities whose distance matrix
/// or colony (every ant's tour and visited marks) needs more memory than the machine has, naming
/// the option and the memory; `instance`, if given, starts the message.
void require_tsp_memory(std::size_t cities, const TspOptions& options,
                        const tsp::SolverSettings& settings, const std::string& instance = "");

/// "mmas, 25 ants, rho 0.2, 3opt (20 neighbours), 12 candidates" from what ran.
std::string describe_algorithm(const tsp::TspProblem& problem, const TspOptions& options,
                               const aco::RunSettings& ran);

}  // namespace antslam::cli
