#include "antslam/qap/solver.hpp"

#include "antslam/aco/backend_factory.hpp"
#include "antslam/qap/local_search.hpp"

namespace antslam::qap {

aco::Parameters resolved_parameters(const SolverSettings& settings) {
  aco::Parameters p = settings.aco;
  if (p.ants == 0 && p.variant == aco::Variant::mmas && settings.local_search)
    p.ants = kMmasQapAnts;
  if (p.ants == 0) p.ants = aco::default_ants(p.variant, 0, false, settings.local_search);
  p.rho = aco::resolved_rho(p, settings.local_search);
  return p;
}

aco::RunResult solve(const QapProblem& problem, const SolverSettings& settings,
                     const aco::Termination& termination, const aco::Observer& observer) {
  const aco::Parameters p = resolved_parameters(settings);
  aco::AnyBackend backend = aco::make_backend(settings.backend, settings.threads);
  if (!settings.local_search)
    return aco::solve(problem, p, termination, std::move(backend), aco::NoLocalSearch{}, observer);
  return aco::solve(problem, p, termination, std::move(backend), PairSwapLocalSearch{}, observer);
}

}  // namespace antslam::qap
