#include "tsp_options_command.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "aco/backend_omp.hpp"
#include "aco/backend_tbb.hpp"
#include "validators.hpp"

namespace antslam::cli {

void add_tsp_options(CLI::App& command, TspOptions& o, bool single_run) {
  constexpr double kBig = std::numeric_limits<double>::max();
  aco::Parameters& p = o.solver.aco;
  if (single_run)
    command.add_option("--variant", o.variant, "ACO variant")
        ->check(CLI::IsMember({"as", "eas", "ras", "acs", "mmas", "hybrid"}))
        ->capture_default_str();
  command.add_option("--local-search", o.local_search, "local search applied to the ants' tours")
      ->check(CLI::IsMember({"none", "2opt", "2.5opt", "3opt"}))
      ->capture_default_str();
  command
      .add_option("--neighbours", o.problem.ls_neighbours,
                  "nearest neighbours the local search tries per city")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1000}))
      ->capture_default_str();
  command
      .add_option("--ls-start", o.ls_start,
                  "cities local search starts from: those with an edge not in the ant's "
                  "previous local optimum, or all (ACOTSP)")
      ->check(CLI::IsMember({"changed", "all"}))
      ->capture_default_str();
  command
      .add_option("--candidates", o.problem.candidates,
                  "nearest neighbours an ant chooses among (candidate list)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1000}))
      ->capture_default_str();
  command
      .add_option("--ls-ants", p.local_search_ants,
                  "apply local search to this many best ants only (0: every ant)")
      ->check(CLI::Range(std::size_t{0}, std::size_t{1'000'000}))
      ->capture_default_str();
  command
      .add_option("--matrix-limit", o.problem.matrix_limit,
                  "store the full distance matrix up to this many cities")
      ->check(non_negative_integer())
      ->capture_default_str();
  command.add_option("--ants", p.ants, "ants per iteration (0: variant default)")
      ->check(CLI::Range(std::size_t{0}, std::size_t{1'000'000}))
      ->capture_default_str();
  if (single_run) {
    command.add_option("--seed", p.seed, "seed of every random choice")
        ->check(non_negative_integer())
        ->capture_default_str();
    command.add_option("--threads", o.threads, "threads building ants")
        ->check(CLI::Range(std::size_t{1}, std::size_t{1024}))
        ->capture_default_str();
  }
  command
      .add_option("--backend", o.backend,
                  "parallel backend (auto: serial on 1 thread, else tbb; with omp on a shared "
                  "machine set OMP_WAIT_POLICY=passive)")
      ->check(CLI::IsMember({"auto", "serial", "omp", "tbb"}))
      ->capture_default_str();
  command.add_option("--alpha", p.alpha, "pheromone exponent")
      ->check(finite_in(0.0, 100.0))
      ->capture_default_str();
  command.add_option("--beta", p.beta, "heuristic exponent")
      ->check(finite_in(0.0, 100.0))
      ->capture_default_str();
  command.add_option("--rho", p.rho, "evaporation rate (0: variant default)")
      ->check(finite_in(0.0, 1.0))
      ->capture_default_str();
  command.add_option("--q0", p.q0, "ACS: probability of the greedy choice")
      ->check(finite_in(0.0, 1.0))
      ->capture_default_str();
  command.add_option("--xi", p.xi, "ACS: local evaporation rate")
      ->check(finite_in(0.0, 1.0))
      ->capture_default_str();
  command.add_option("--elite-weight", p.elite_weight, "EAS: weight of the best-so-far (0: n)")
      ->check(finite_in(0.0, kBig))
      ->capture_default_str();
  command.add_option("--rank-width", p.rank_width, "RAS: ranked ants w")
      ->check(CLI::Range(std::size_t{2}, std::size_t{100000}))
      ->capture_default_str();
  command.add_option("--p-best", p.p_best, "MMAS: p_best setting tau_min")
      ->check(finite_in(1e-12, 1.0 - 1e-12))
      ->capture_default_str();
  command.add_option("--restarts", p.restarts, "MMAS: re-initialise trails on stagnation")
      ->capture_default_str();
  command.add_option("--p0", p.p0, "hybrid: probability of a uniform choice")
      ->check(finite_in(0.0, 1.0))
      ->capture_default_str();
  command
      .add_option("--glob-best-freq", p.glob_best_freq,
                  "hybrid: every this-th iteration only the two best ants deposit")
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1000000}))
      ->capture_default_str();
  command.add_option("--tau-max", p.tau_max, "hybrid: pheromone cap")
      ->check(finite_in(1e-300, kBig))
      ->capture_default_str();
  command.add_option("--tau-init", p.tau_init, "hybrid: initial pheromone")
      ->check(finite_in(1e-300, kBig))
      ->capture_default_str();
  command
      .add_option("--hybrid-deposit", o.solver.hybrid_deposit,
                  "hybrid: deposit numerator Q (0: nearest-neighbour tour length)")
      ->check(finite_in(0.0, kBig))
      ->capture_default_str();
}

tsp::SolverSettings solver_settings(const TspOptions& o) {
  tsp::SolverSettings s = o.solver;
  const auto variant = aco::parse_variant(o.variant);
  if (!variant) throw std::invalid_argument("--variant: unknown variant '" + o.variant + "'");
  s.aco.variant = *variant;
  const auto kind = tsp::parse_local_search(o.local_search);
  if (!kind) throw std::invalid_argument("--local-search: unknown '" + o.local_search + "'");
  s.local_search.kind = *kind;
  s.local_search.neighbours = o.problem.ls_neighbours;
  s.local_search.queue_changed_only = o.ls_start == "changed";
  if (s.aco.tau_init > s.aco.tau_max)
    throw std::invalid_argument("--tau-init must not exceed --tau-max");
  return s;
}

tsp::ProblemSettings problem_settings(const TspOptions& o) { return o.problem; }

std::string backend_name(const TspOptions& o) {
  if (o.backend != "auto") return o.backend;
  // TBB, not OpenMP: OpenMP's default spin-waiting at the end of every iteration costs half
  // the iterations when other processes compete for the cores (docs/tsp.md, "Threads").
  return o.threads == 1 ? "serial" : "tbb";
}

aco::AnyBackend make_backend(const TspOptions& o) {
  const std::string name = backend_name(o);
  if (name == "serial") {
    if (o.threads != 1) throw std::invalid_argument("--backend serial runs on exactly 1 thread");
    return aco::SerialBackend{};
  }
  if (name == "omp") return aco::OmpBackend(o.threads);
  if (name == "tbb") return aco::TbbBackend(o.threads);
  throw std::invalid_argument("--backend: unknown backend '" + o.backend + "'");
}

std::string describe_algorithm(const tsp::TspProblem& problem, const TspOptions& o) {
  const tsp::SolverSettings s = solver_settings(o);
  std::ostringstream out;
  out << o.variant << ", " << tsp::resolved_ants(problem, s) << " ants, rho "
      << tsp::resolved_rho(s) << ", " << o.local_search;
  if (s.local_search.kind != tsp::LocalSearchKind::none)
    out << " (" << problem.neighbours(0).size() << " neighbours)";
  out << ", " << problem.candidates(0).size() << " candidates";
  return out.str();
}

}  // namespace antslam::cli
