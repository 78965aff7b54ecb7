#pragma once
// The named ACO variants as policy combinations, their documented defaults, and solve(): the
// plain entry point that picks the variant at run time.
//
//   variant  rule                          update          default ants   default rho
//   as       RandomProportional            AntSystemUpdate n (TSP) / 20   0.5
//   eas      RandomProportional            ElitistUpdate   n (TSP) / 20   0.5
//   ras      RandomProportional            RankUpdate      n (TSP) / 20   0.1
//   acs      PseudoRandomProportional(q0)  AcsUpdate       10             0.1
//   mmas     RandomProportional            MaxMinUpdate    n (TSP) / 20   0.02
//   hybrid   UniformExploration(p0)        HybridUpdate    20             1 (docs/slamgraph.md)
// With local search, every variant except hybrid and acs defaults to 25 ants, and MMAS to
// rho = 0.2 (Dorigo & Stuetzle 2004, Table 3.3 and Sec. 3.7.2; ACOTSP).

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

#include "antslam/aco/colony.hpp"
#include "antslam/aco/rules.hpp"
#include "antslam/aco/update_acs.hpp"
#include "antslam/aco/update_ant_system.hpp"
#include "antslam/aco/update_hybrid.hpp"
#include "antslam/aco/update_mmas.hpp"
#include "antslam/aco/variant.hpp"

namespace antslam::aco {

/// Every knob of every variant. Zero means "the variant's default" where noted.
struct Parameters {
  Variant variant = Variant::mmas;    ///< which algorithm
  std::size_t ants = 0;               ///< ants per iteration; 0 = default (table above)
  double alpha = 1.0;                 ///< pheromone exponent, eq. (1)
  double beta = 2.0;                  ///< heuristic exponent, eq. (1) (ACOTSP's default)
  double rho = 0.0;                   ///< evaporation rate of eq. (2); 0 = default (table above)
  std::uint64_t seed = 1;             ///< seed of every random stream
  std::size_t local_search_ants = 0;  ///< 0: local search on every ant; k: on the k best
  FocusedSettings focused{};  ///< focused construction (permutation problems); off by default
  // Ant Colony System
  double q0 = 0.9;  ///< probability of the greedy choice
  double xi = 0.1;  ///< local evaporation rate
  // Elitist and rank-based Ant System
  double elite_weight = 0.0;   ///< EAS weight e of the best-so-far deposit; 0 = n
  std::size_t rank_width = 6;  ///< RAS w: the w-1 best ants and the best-so-far deposit
  // MAX-MIN Ant System
  double p_best = 0.05;                ///< sets tau_min (Stuetzle & Hoos 2000)
  bool restarts = true;                ///< re-initialise trails on stagnation
  std::uint64_t restart_stagnant = 0;  ///< k > 0: restart when the restart-best is k iterations
                                       ///< old; 0: ACOTSP's branching-factor test
  // AntSLAM hybrid (paper Sec. IV values)
  double p0 = 0.3;  ///< probability of a uniform choice
  std::uint64_t glob_best_freq =
      5;                        ///< every this-th iteration only global- and iteration-best deposit
  double tau_max = 10000.0;     ///< pheromone cap
  double tau_init = 100.0;      ///< initial pheromone
  double hybrid_deposit = 1.0;  ///< numerator Q of the deposit Q/W (eq. 12: 1)
};

/// Throws std::invalid_argument "aco: FIELD must be ..." for the first nonsensical parameter.
inline void validate(const Parameters& p) {
  const auto require = [](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("aco: ") + what);
  };
  const auto finite_at_least = [](double v, double lo) { return std::isfinite(v) && v >= lo; };
  require(finite_at_least(p.alpha, 0.0), "alpha must be a finite number >= 0");
  require(finite_at_least(p.beta, 0.0), "beta must be a finite number >= 0");
  require(p.rho >= 0.0 && p.rho <= 1.0, "rho must be in [0, 1] (0: the variant's default)");
  require(p.q0 >= 0.0 && p.q0 <= 1.0, "q0 must be in [0, 1]");
  require(p.xi >= 0.0 && p.xi <= 1.0, "xi must be in [0, 1]");
  require(p.p0 >= 0.0 && p.p0 <= 1.0, "p0 must be in [0, 1]");
  require(finite_at_least(p.elite_weight, 0.0), "elite_weight must be a finite number >= 0");
  require(p.rank_width >= 1, "rank_width must be >= 1");
  require(p.p_best > 0.0 && p.p_best < 1.0, "p_best must be in (0, 1)");
  require(p.glob_best_freq >= 1, "glob_best_freq must be >= 1");
  require(std::isfinite(p.tau_max) && p.tau_init > 0.0 && p.tau_max >= p.tau_init,
          "need 0 < tau_init <= tau_max, both finite");
  require(std::isfinite(p.hybrid_deposit) && p.hybrid_deposit > 0.0,
          "hybrid_deposit must be a finite number > 0");
}

/// Default number of ants; `decisions` is the number of cities (or layers).
constexpr std::size_t default_ants(Variant v, std::size_t decisions, bool permutation,
                                   bool local_search) {
  if (v == Variant::hybrid) return 20;
  if (v == Variant::acs) return 10;
  if (local_search) return 25;
  return permutation ? decisions : 20;
}

constexpr double default_rho(Variant v, bool local_search) {
  switch (v) {
    case Variant::ant_system:
    case Variant::elitist:
      return 0.5;
    case Variant::rank_based:
    case Variant::acs:
      return 0.1;
    case Variant::mmas:
      return local_search ? 0.2 : 0.02;
    case Variant::hybrid:
      return HybridUpdate{}.rho;
  }
  return 0.1;
}

/// p.rho, or the variant's default when it is 0.
constexpr double resolved_rho(const Parameters& p, bool local_search) {
  return p.rho > 0.0 ? p.rho : default_rho(p.variant, local_search);
}

/// Calls f(rule, update) with the policies of p.variant, configured from p; `rho` is the
/// resolved evaporation rate. The single place where a variant name becomes types.
template <class F>
decltype(auto) with_variant_policies(const Parameters& p, double rho, F&& f) {
  switch (p.variant) {
    case Variant::ant_system:
      return f(RandomProportional{}, AntSystemUpdate{rho});
    case Variant::elitist:
      return f(RandomProportional{}, ElitistUpdate{rho, p.elite_weight});
    case Variant::rank_based:
      return f(RandomProportional{}, RankUpdate{rho, p.rank_width});
    case Variant::acs:
      return f(PseudoRandomProportional{p.q0}, AcsUpdate{rho, p.xi});
    case Variant::mmas: {
      return f(RandomProportional{}, MaxMinUpdate({.rho = rho,
                                                   .p_best = p.p_best,
                                                   .reinitialize = p.restarts,
                                                   .restart_stagnant = p.restart_stagnant}));
    }
    case Variant::hybrid:
      return f(UniformExploration{p.p0},
               HybridUpdate{rho, p.glob_best_freq, p.tau_max, p.tau_init, p.hybrid_deposit});
  }
  throw std::invalid_argument("unknown ACO variant");
}

/// Colony settings of p for a problem with `decisions` decisions.
inline ColonySettings colony_settings(const Parameters& p, std::size_t decisions, bool permutation,
                                      bool local_search) {
  ColonySettings settings;
  settings.ants =
      p.ants > 0 ? p.ants : default_ants(p.variant, decisions, permutation, local_search);
  settings.alpha = p.alpha;
  settings.beta = p.beta;
  settings.seed = p.seed;
  settings.local_search_ants = p.local_search_ants;
  settings.focused = p.focused;
  return settings;
}

/// Colony settings of p on `problem` (p validated first): ants scale with the problem when its
/// family says how (FamilyWithDefaultAnts), else the variant's fixed default.
template <class Problem>
ColonySettings colony_settings_for(const Problem& problem, const Parameters& p, bool local_search) {
  validate(p);
  using Family = family_t<Problem>;
  if constexpr (FamilyWithDefaultAnts<Family, Problem>) {
    return colony_settings(p, Family::default_ants(problem), true, local_search);
  } else {
    return colony_settings(p, 0, false, local_search);
  }
}

/// Builds the colony of p.variant on `problem` (defaults resolved) and returns f(colony): the
/// one place where Parameters become a Colony, for callers that step it themselves.
template <class Problem, class LocalSearch = NoLocalSearch, class Exec = AnyBackend, class F>
decltype(auto) with_colony(const Problem& problem, const Parameters& p, Exec backend,
                           LocalSearch local_search, F&& f) {
  constexpr bool kLs = !std::is_same_v<LocalSearch, NoLocalSearch>;
  const ColonySettings settings = colony_settings_for(problem, p, kLs);
  return with_variant_policies(p, resolved_rho(p, kLs), [&](auto rule, auto update) {
    Colony<Problem, decltype(rule), decltype(update), LocalSearch, Exec> colony(
        problem, settings, rule, update, std::move(local_search), std::move(backend));
    return f(colony);
  });
}

/// Runs the chosen variant on `problem` with any backend and local search; the result records
/// the settings that ran.
template <class Problem, class LocalSearch = NoLocalSearch, class Exec = AnyBackend>
RunResult solve(const Problem& problem, const Parameters& p, const Termination& termination,
                Exec backend = {}, LocalSearch local_search = {}, const Observer& observer = {}) {
  RunResult result = with_colony(problem, p, std::move(backend), std::move(local_search),
                                 [&](auto& colony) { return colony.run(termination, observer); });
  result.settings.variant = p.variant;
  result.settings.rho = resolved_rho(p, result.settings.local_search);
  return result;
}

}  // namespace antslam::aco
