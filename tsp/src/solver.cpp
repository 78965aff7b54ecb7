#include "antslam/tsp/solver.hpp"

#include "antslam/aco/backend_factory.hpp"
#include "antslam/aco/permutation_family.hpp"

namespace antslam::tsp {

namespace {
bool has_local_search(const SolverSettings& s) {
  return s.local_search.kind != LocalSearchKind::none;
}
}  // namespace

double nearest_neighbour_length(const TspProblem& problem) {
  return aco::PermutationFamily<TspProblem>::nearest_neighbour_cost(problem);
}

aco::Parameters resolved_parameters(const TspProblem& problem, const SolverSettings& settings) {
  aco::Parameters p = settings.aco;
  p.ants = resolved_ants(problem, settings);
  p.rho = resolved_rho(settings);
  p.focused.min_new_edges = settings.focused_edges.value_or(default_focused_edges(p.variant));
  if (p.variant == aco::Variant::hybrid)
    p.hybrid_deposit =
        settings.hybrid_deposit > 0.0 ? settings.hybrid_deposit : nearest_neighbour_length(problem);
  return p;
}

std::size_t resolved_ants(const TspProblem& problem, const SolverSettings& settings) {
  return resolved_ants(problem.size(), settings);
}

std::size_t resolved_ants(std::size_t cities, const SolverSettings& settings) {
  if (settings.aco.ants > 0) return settings.aco.ants;
  return aco::default_ants(settings.aco.variant, cities, true, has_local_search(settings));
}

double colony_memory_bytes(std::size_t cities, std::size_t ants) {
  return (sizeof(std::uint32_t) + sizeof(std::uint8_t)) * static_cast<double>(cities) *
         static_cast<double>(ants);
}

double resolved_rho(const SolverSettings& settings) {
  if (settings.aco.rho > 0.0) return settings.aco.rho;
  return aco::default_rho(settings.aco.variant, has_local_search(settings));
}

aco::RunResult solve(const TspProblem& problem, const SolverSettings& settings,
                     const aco::Termination& termination, const aco::Observer& observer) {
  const aco::Parameters p = resolved_parameters(problem, settings);
  aco::AnyBackend backend = aco::make_backend(settings.backend, settings.threads);
  if (!has_local_search(settings))
    return aco::solve(problem, p, termination, std::move(backend), aco::NoLocalSearch{}, observer);
  return aco::solve(problem, p, termination, std::move(backend),
                    TourLocalSearch(settings.local_search), observer);
}

aco::IslandResult solve_islands(const TspProblem& problem, const SolverSettings& settings,
                                const aco::Termination& termination,
                                const aco::IslandSettings& islands, const aco::Exchange& exchange,
                                const aco::IslandObserver& observer) {
  const aco::Parameters p = resolved_parameters(problem, settings);
  const auto make_backend = [&] { return aco::make_backend(settings.backend, settings.threads); };
  if (!has_local_search(settings))
    return aco::solve_islands(problem, p, termination, make_backend, aco::NoLocalSearch{}, islands,
                              exchange, observer);
  return aco::solve_islands(problem, p, termination, make_backend,
                            TourLocalSearch(settings.local_search), islands, exchange, observer);
}

}  // namespace antslam::tsp
