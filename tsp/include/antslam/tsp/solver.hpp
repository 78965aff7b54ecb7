#pragma once
// The plain entry point: any ACO variant with any TSP local search on any backend, chosen at
// run time (aco::solve with the TSP's defaults).
//
// TSP defaults on top of the engine's (aco/variants.hpp): focused construction for MAX-MIN (8 new
// edges per ant); ants = n without local search and 25 with it (ACS 10, hybrid 20); the hybrid's
// deposit numerator Q is the nearest-neighbour tour length C_nn, so that a tour as good as the
// greedy one deposits 1 (with Q = 1 of eq. 12 a deposit of 1/L ~ 1e-5 would be lost against
// tau_init = 100).

#include <cstddef>
#include <optional>

#include "antslam/aco/backend_kind.hpp"
#include "antslam/aco/colony.hpp"
#include "antslam/aco/islands.hpp"
#include "antslam/aco/termination.hpp"
#include "antslam/aco/variants.hpp"
#include "antslam/tsp/local_search.hpp"
#include "antslam/tsp/problem.hpp"

namespace antslam::tsp {

/// Focused construction's default for the TSP: MAX-MIN ants change the previous iteration's
/// best tour in at least 8 edges (FocusedACO, Skinderowicz 2022); the other variants build
/// every tour from nothing (ACS's greedy choices rarely leave the source: with focus it stalls
/// on eil51). Chosen on generated instances only (docs/tsp-results.md, "Focused construction").
constexpr std::size_t default_focused_edges(aco::Variant v) {
  return v == aco::Variant::mmas ? 8 : 0;
}

struct SolverSettings {
  aco::Parameters aco;  ///< variant and its parameters (0 = variant default); aco.focused's
                        ///< min_new_edges is set from focused_edges
  std::optional<std::size_t> focused_edges;  ///< new edges per focused ant; 0 = off; empty =
                                             ///< default_focused_edges(variant)
  LocalSearchSettings local_search;  ///< improves every ant, or the aco.local_search_ants best
  double hybrid_deposit = 0.0;       ///< hybrid's deposit numerator Q; 0 = C_nn (tour length)
  aco::BackendKind backend = aco::BackendKind::automatic;  ///< runs the ants of an iteration
  std::size_t threads = 1;  ///< threads building ants (0 = all cores); results do not depend on it
};

/// Length of the nearest-neighbour tour from city 0 over the candidate lists (C_nn).
double nearest_neighbour_length(const TspProblem& problem);

/// The engine parameters actually used for `problem` (resolves the TSP defaults above).
aco::Parameters resolved_parameters(const TspProblem& problem, const SolverSettings& settings);
/// Ants per iteration and evaporation rate actually used.
std::size_t resolved_ants(const TspProblem& problem, const SolverSettings& settings);
std::size_t resolved_ants(std::size_t cities, const SolverSettings& settings);
/// Bytes the colony holds for its ants at the least: each ant's tour (4 bytes a city) and its
/// visited marks (1 byte a city). Without local search the default is one ant per city, so this
/// grows as n^2 (a 1,000,000-city instance: 5 TB).
double colony_memory_bytes(std::size_t cities, std::size_t ants);
double resolved_rho(const SolverSettings& settings);

/// Runs settings.aco.variant on settings.backend; the result records the settings that ran.
/// Throws std::invalid_argument for the serial backend on more than one thread.
aco::RunResult solve(const TspProblem& problem, const SolverSettings& settings,
                     const aco::Termination& termination, const aco::Observer& observer = {});

/// The island model (aco/islands.hpp) of settings.aco.variant: this process runs
/// islands.first .. first + local - 1 of the K colonies, each on its own settings.backend with
/// settings.threads; `exchange` gathers the colonies' offers (aco::in_process_exchange when all
/// run here). Colony c is seeded with aco::colony_seed(settings.aco.seed, c).
aco::IslandResult solve_islands(const TspProblem& problem, const SolverSettings& settings,
                                const aco::Termination& termination,
                                const aco::IslandSettings& islands,
                                const aco::Exchange& exchange = aco::in_process_exchange,
                                const aco::IslandObserver& observer = {});

}  // namespace antslam::tsp
