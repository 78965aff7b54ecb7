#pragma once
// The files of one TSP run (`antslam tsp --trace-csv`, `--json`): the best tour's length after
// every iteration (CSV), and a JSON summary (the program writes its text with io::json_text) with
// the instance, every setting that ran, the result and, for the island model, each colony's best.

#include <iosfwd>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>

#include "antslam/aco/colony.hpp"
#include "antslam/aco/islands.hpp"
#include "antslam/tsp/problem.hpp"
#include "antslam/tsp/solver.hpp"

namespace antslam::tsp {

/// iteration,elapsed_s,iteration_best,global_best: a row per iteration, 15 significant digits.
void write_trace_csv(std::ostream& out, std::span<const aco::IterationReport> trace);

/// The run's summary as a JSON document. `length` is the best tour's length, `optimum` the
/// instance's if known, `setup_s` the seconds before the budget (reading, candidate lists, the
/// colony); `islands` and `island` for an island run. Its "settings" hold every setting that
/// ran: the budget, every engine parameter as resolved for the instance, the local search.
nlohmann::json run_json(const TspProblem& problem, const SolverSettings& settings,
                        const aco::Termination& budget, const aco::RunResult& result, double length,
                        std::optional<double> optimum, double setup_s,
                        const std::optional<aco::IslandSettings>& islands,
                        const std::optional<aco::IslandResult>& island);

}  // namespace antslam::tsp
