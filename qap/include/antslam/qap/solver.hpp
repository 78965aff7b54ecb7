#pragma once
// The plain entry point: any ACO variant of the engine on a QAP, with or without the pair-swap
// local search, on any backend, chosen at run time (aco::solve with the QAP's defaults).
//
// The recommended variant is MAX-MIN Ant System with pair-swap local search, as MMAS-QAP
// (Stuetzle & Hoos 2000, Sec. 5): 5 ants, trail persistence 0.8 (our evaporation rate rho =
// 1 - 0.8 = 0.2), tau_max = 1 / (rho f(best-so-far)), tau_min = tau_max / 2n, no heuristic,
// the iteration-best or the best-so-far ant depositing, and trails re-initialised on stagnation
// (aco/update_mmas.hpp). Other variants keep the engine's defaults (aco/variants.hpp).

#include <cstddef>

#include "antslam/aco/backend_kind.hpp"
#include "antslam/aco/colony.hpp"
#include "antslam/aco/termination.hpp"
#include "antslam/aco/variants.hpp"
#include "antslam/qap/problem.hpp"

namespace antslam::qap {

/// MMAS-QAP's colony size with local search (Stuetzle & Hoos 2000).
inline constexpr std::size_t kMmasQapAnts = 5;

struct SolverSettings {
  aco::Parameters aco;       ///< variant and its parameters (0 = the defaults above)
  bool local_search = true;  ///< pair-swap local search on every ant (or the aco.local_search_ants
                             ///< best)
  aco::BackendKind backend = aco::BackendKind::automatic;  ///< runs the ants of an iteration
  std::size_t threads = 1;  ///< threads building ants (0 = all cores); results do not depend on it
};

/// The engine parameters actually used (ants and rho resolved).
aco::Parameters resolved_parameters(const SolverSettings& settings);

/// Runs settings.aco.variant; the result's best path is the assignment (path[i]: the location
/// of facility i) and its cost the exact QAP cost. Throws std::invalid_argument for the serial
/// backend on more than one thread.
aco::RunResult solve(const QapProblem& problem, const SolverSettings& settings,
                     const aco::Termination& termination, const aco::Observer& observer = {});

}  // namespace antslam::qap
