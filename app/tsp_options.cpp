#include "tsp_options.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "antslam/aco/variant.hpp"
#include "antslam/io/memory.hpp"
#include "backend_option.hpp"
#include "validators.hpp"

namespace antslam::cli {

void add_tsp_options(CLI::App& command, TspOptions& o, bool single_run) {
  constexpr double kBig = std::numeric_limits<double>::max();
  aco::Parameters& p = o.solver.aco;
  if (single_run)
    command.add_option("--variant", o.variant, "ACO variant")
        ->check(CLI::IsMember(aco::variant_names()))
        ->capture_default_str();
  command.add_option("--local-search", o.local_search, "local search applied to the ants' tours")
      ->check(CLI::IsMember({"none", "2opt", "2.5opt", "3opt"}))
      ->capture_default_str();
  command
      .add_option_function<std::string>(
          "--localsearch",
          [&o](const std::string& level) { o.local_search = acotsp_local_search(level); },
          "ACOTSP's name: 0 none, 1 2opt, 2 2.5opt, 3 3opt")
      ->check(CLI::IsMember({"0", "1", "2", "3"}));
  command
      .add_option_function<int>(
          "--dlb", [&o](int on) { o.ls_start = on != 0 ? "changed" : "all"; },
          "ACOTSP's don't-look bits: 1 keeps them between an ant slot's searches (--ls-start "
          "changed), 0 starts every search with every city active (--ls-start all)")
      ->check(CLI::IsMember({0, 1}));
  command
      .add_option("--neighbours,--nnls", o.problem.ls_neighbours,
                  "nearest neighbours the local search tries per city")
      ->check(count_in(1, 1000))
      ->capture_default_str();
  command
      .add_option("--ls-start", o.ls_start,
                  "cities local search starts from: those with an edge not in the ant's "
                  "previous local optimum, or all (ACOTSP)")
      ->check(CLI::IsMember({"changed", "all"}))
      ->capture_default_str();
  command
      .add_option("--two-level-from", o.solver.local_search.two_level_from,
                  "cities from which local search moves run on a two-level tour (O(sqrt n) a "
                  "move) instead of an array (O(n))")
      ->check(count_in(0, 1'000'000'000))
      ->capture_default_str();
  command
      .add_option("--candidates,--nnants", o.problem.candidates,
                  "nearest neighbours an ant chooses among (candidate list)")
      ->check(count_in(1, 1000))
      ->capture_default_str();
  command
      .add_option("--ls-ants", p.local_search_ants,
                  "apply local search to this many best ants only (0: every ant)")
      ->check(count_in(0, 1'000'000))
      ->capture_default_str();
  command
      .add_option("--matrix-limit", o.problem.matrix_limit,
                  "store the full distance matrix (4 n^2 bytes) up to this many cities")
      ->check(count_in(0, 1'000'000))
      ->capture_default_str();
  command.add_option("--ants", p.ants, "ants per iteration (0: variant default)")
      ->check(count_in(0, 1'000'000))
      ->capture_default_str();
  if (single_run) {
    command.add_option("--seed", p.seed, "seed of every random choice")
        ->check(non_negative_integer())
        ->capture_default_str();
    command.add_option("--threads", o.threads, "threads building ants")
        ->check(count_in(1, 1024))
        ->capture_default_str();
  }
  add_backend_option(command, o.backend);
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
  command
      .add_option("--focused-edges", o.solver.focused_edges,
                  "focused construction: ants change the source tour and copy it after adding "
                  "this many edges of their own (0: build every tour from nothing; default: 8 "
                  "for mmas, 0 for the other variants)")
      ->check(count_in(0, 1'000'000));
  command
      .add_option("--source-global-best", p.focused.global_best_source,
                  "focused construction: probability that the source is the best-so-far tour "
                  "(else the previous iteration's best)")
      ->check(finite_in(0.0, 1.0))
      ->capture_default_str();
  command
      .add_option("--elite-weight,--elitistants", p.elite_weight,
                  "EAS: weight of the best-so-far (0: n)")
      ->check(finite_in(0.0, kBig))
      ->capture_default_str();
  command.add_option("--rank-width,--rasranks", p.rank_width, "RAS: ranked ants w")
      ->check(count_in(2, 100000))
      ->capture_default_str();
  command.add_option("--p-best", p.p_best, "MMAS: p_best setting tau_min")
      ->check(finite_in(1e-12, 1.0 - 1e-12))
      ->capture_default_str();
  command.add_option("--restarts", p.restarts, "MMAS: re-initialise trails on stagnation")
      ->capture_default_str();
  command
      .add_option("--restart-stagnant", p.restart_stagnant,
                  "MMAS: stagnation is a restart-best this many iterations old (0 = converged "
                  "trails and 250 iterations, as ACOTSP)")
      ->check(count_in(0, 100'000'000))
      ->capture_default_str();
  command.add_option("--p0", p.p0, "hybrid: probability of a uniform choice")
      ->check(finite_in(0.0, 1.0))
      ->capture_default_str();
  command
      .add_option("--glob-best-freq", p.glob_best_freq,
                  "hybrid: every this-th iteration only the two best ants deposit")
      ->check(count_in(1, 1000000))
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

std::string acotsp_local_search(const std::string& level) {
  static const char* const kNames[] = {"none", "2opt", "2.5opt", "3opt"};
  if (level.size() != 1 || level[0] < '0' || level[0] > '3')
    throw std::invalid_argument("--localsearch: '" + level + "' is not 0, 1, 2 or 3");
  return kNames[level[0] - '0'];
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
  s.backend = parse_backend_option(o.backend);
  s.threads = o.threads;
  aco::resolve(s.backend, s.threads);  // serial on more than one thread fails here, up front
  return s;
}

tsp::ProblemSettings problem_settings(const TspOptions& o) { return o.problem; }

void require_tsp_memory(std::size_t cities, const TspOptions& o,
                        const tsp::SolverSettings& settings, const std::string& instance) {
  const std::string where = instance.empty() ? "" : instance + ": ";
  const auto n = static_cast<double>(cities);
  if (cities <= o.problem.matrix_limit)
    io::require_memory(where + "--matrix-limit " + std::to_string(o.problem.matrix_limit) +
                           " (the distance matrix)",
                       4.0 * n * n);
  const std::size_t ants = tsp::resolved_ants(cities, settings);
  io::require_memory(where + "--ants " + std::to_string(ants) + " on " + std::to_string(cities) +
                         " cities (each ant's tour)",
                     tsp::colony_memory_bytes(cities, ants));
}

std::string describe_algorithm(const tsp::TspProblem& problem, const TspOptions& o,
                               const aco::RunSettings& ran) {
  std::ostringstream out;
  out << o.variant << ", " << ran.colony.ants << " ants, rho " << ran.rho << ", " << o.local_search;
  if (ran.local_search) out << " (" << problem.neighbours(0).size() << " neighbours)";
  out << ", " << problem.candidates(0).size() << " candidates";
  if (ran.colony.focused.enabled())
    out << ", focused (" << ran.colony.focused.min_new_edges << " new edges, source best-so-far "
        << ran.colony.focused.global_best_source << ")";
  return out.str();
}

}  // namespace antslam::cli
