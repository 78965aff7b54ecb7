#include "antslam/tsp/run_io.hpp"

#include <iomanip>
#include <limits>
#include <ostream>

#include "antslam/aco/backend_kind.hpp"
#include "antslam/aco/parameter_fields.hpp"
#include "antslam/aco/variant.hpp"

namespace antslam::tsp {

void write_trace_csv(std::ostream& out, std::span<const aco::IterationReport> trace) {
  out << "iteration,elapsed_s,iteration_best,global_best\n" << std::setprecision(15);
  for (const aco::IterationReport& r : trace)
    out << r.iteration << ',' << r.elapsed_s << ',' << r.iteration_best << ',' << r.global_best
        << '\n';
}

namespace {

/// The budget, the engine's parameters as resolved for the problem, and the local search.
nlohmann::json settings_json(const TspProblem& problem, const SolverSettings& settings,
                             const aco::Termination& budget) {
  const aco::Parameters resolved = resolved_parameters(problem, settings);
  nlohmann::json engine;
  aco::for_each_parameter(resolved,
                          [&](const char* name, const auto& value) { engine[name] = value; });
  engine["local_search_ants"] = resolved.local_search_ants;
  engine["focused_edges"] = resolved.focused.min_new_edges;
  engine["focused_global_best_source"] = resolved.focused.global_best_source;
  nlohmann::json limits = {{"iterations", budget.max_iterations},
                           {"time_limit_s", budget.time_limit_s},
                           {"cpu_time_limit_s", budget.cpu_time_limit_s},
                           {"stagnation_iterations", budget.stagnation_iterations}};
  limits["target_length"] = budget.target_cost > -std::numeric_limits<double>::infinity()
                                ? nlohmann::json(budget.target_cost)
                                : nlohmann::json(nullptr);
  const LocalSearchSettings& ls = settings.local_search;
  return {{"budget", limits},
          {"aco", engine},
          {"local_search",
           {{"kind", to_string(ls.kind)},
            {"neighbours", ls.neighbours},
            {"queue_changed_only", ls.queue_changed_only},
            {"two_level_from", ls.two_level_from}}}};
}

}  // namespace

nlohmann::json run_json(const TspProblem& problem, const SolverSettings& settings,
                        const aco::Termination& budget, const aco::RunResult& result, double length,
                        std::optional<double> optimum, double setup_s,
                        const std::optional<aco::IslandSettings>& islands,
                        const std::optional<aco::IslandResult>& island) {
  const Instance& instance = problem.instance();
  nlohmann::json j = {{"instance", instance.name()},
                      {"cities", instance.size()},
                      {"edge_weight_type", to_string(instance.type())},
                      {"variant", aco::to_string(settings.aco.variant)},
                      {"ants", result.settings.colony.ants},
                      {"rho", result.settings.rho},
                      {"local_search", to_string(settings.local_search.kind)},
                      {"neighbours", problem.neighbours(0).size()},
                      {"candidates", problem.candidates(0).size()},
                      {"focused_edges", result.settings.colony.focused.min_new_edges},
                      {"seed", settings.aco.seed},
                      {"threads", result.settings.threads},
                      {"backend", aco::to_string(result.settings.backend)},
                      {"best_length", length},
                      {"iterations", result.iterations},
                      {"best_iteration", result.best_iteration},
                      {"elapsed_s", result.elapsed_s},
                      {"setup_s", setup_s},
                      {"time_to_best_s", result.time_to_best_s},
                      {"stop_reason", aco::to_string(result.reason)},
                      {"settings", settings_json(problem, settings, budget)}};
  if (islands && island) {
    j["colonies"] = islands->colonies;
    j["exchange_every"] = islands->exchange_every;
    j["topology"] = aco::to_string(islands->topology);
    j["best_colony"] = island->best_colony;
    j["colony_best_lengths"] = island->colony_best;
    j["exchanges"] = island->exchanges;
    j["exchange_s"] = island->exchange_s;
  }
  if (optimum) {
    j["optimum"] = *optimum;
    j["excess_percent"] = 100.0 * (length / *optimum - 1.0);
  }
  return j;
}

}  // namespace antslam::tsp
