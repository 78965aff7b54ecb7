#include "antslam/clique/aco_search.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "antslam/aco/backend_factory.hpp"
#include "antslam/clique/exact.hpp"
#include "antslam/clique/greedy.hpp"
#include "antslam/clique/local_search.hpp"
#include "antslam/clique/problem.hpp"

namespace antslam::clique {

AcoSearchResult maximum_clique_aco(const Graph& graph, const AcoSearchSettings& settings) {
  if (graph.size() == 0) throw std::invalid_argument("ant clique search: the graph is empty");
  const aco::Termination& t = settings.termination;
  if (t.max_iterations == 0 && !(t.time_limit_s > 0.0) && !(t.cpu_time_limit_s > 0.0) &&
      t.stagnation_iterations == 0)
    throw std::invalid_argument(
        "ant clique search: set iterations, a time budget or stagnation (the colouring bound "
        "alone may never be reached)");
  const auto start = std::chrono::steady_clock::now();
  const CliqueProblem problem(graph);
  const double bound = colouring_bound(graph);
  aco::Termination termination = t;
  termination.target_cost = std::max(termination.target_cost, problem.cost_of_weight(bound));
  // The backend type-erased (one indirect call per iteration phase, the per-ant work stays
  // static): a third of the instantiations of with_backend.
  const auto solve = [&](auto local_search) {
    return aco::solve(problem, settings.parameters, termination,
                      aco::make_backend(settings.backend, settings.threads), local_search);
  };
  const aco::RunResult run = settings.local_search
                                 ? solve(SwapLocalSearch{.plateau_steps = settings.plateau_steps})
                                 : solve(aco::NoLocalSearch{});

  AcoSearchResult result;
  result.iterations = run.iterations;
  result.reason = run.reason;
  result.clique.vertices = run.best.path;
  std::sort(result.clique.vertices.begin(), result.clique.vertices.end());
  result.clique.weight = weight_of(graph, result.clique.vertices);
  result.clique.upper_bound = bound;
  result.clique.optimal = result.clique.weight >= bound;
  if (settings.proof_nodes > 0 && !result.clique.optimal) {
    const ExactResult exact = maximum_clique_exact(
        graph, {.time_limit_s = 0.0, .max_nodes = settings.proof_nodes}, result.clique.vertices);
    result.proof_nodes = exact.nodes;
    result.clique.vertices = exact.clique.vertices;
    result.clique.weight = exact.clique.weight;
    result.clique.optimal = exact.clique.optimal;
    if (exact.clique.optimal) result.clique.upper_bound = exact.clique.weight;
  }
  result.clique.elapsed_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace antslam::clique
