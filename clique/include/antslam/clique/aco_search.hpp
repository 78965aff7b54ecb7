#pragma once
// Maximum clique by the ant colony engine: any variant of aco::kVariants on any backend, on
// CliqueProblem, each ant's clique improved by (1,2)-swaps (and, if asked, a plateau walk;
// local_search.hpp) unless switched off. The run stops at its termination criteria or as soon
// as a clique reaches the colouring bound (then it is proven maximum). If asked (proof_nodes),
// branch and bound then starts from the ants' clique, whose weight prunes from the first node,
// for at most that many nodes: within them it proves the clique maximum or finds a heavier one;
// a node budget, not a clock, so the result stays the same on every machine.

#include <cstddef>
#include <cstdint>

#include "antslam/aco/backend_kind.hpp"
#include "antslam/aco/termination.hpp"
#include "antslam/aco/variants.hpp"
#include "antslam/clique/graph.hpp"

namespace antslam::clique {

struct AcoSearchSettings {
  aco::Parameters parameters = default_parameters();  ///< variant, ants, rho, seed, ...
  aco::Termination termination = {.max_iterations = 100, .stagnation_iterations = 20};
  ///< iterations (count), wall-clock budget (s), stagnation (iterations); the colouring bound is
  ///< always the target
  bool local_search = true;          ///< (1,2)-swaps on every ant's clique
  std::size_t plateau_steps = 0;     ///< then a plateau walk of at most this many moves; 0 = none
  std::uint64_t proof_nodes = 1000;  ///< then branch and bound from the ants' clique, at most
                                     ///< this many nodes (chosen on generated graphs); 0 = none
  aco::BackendKind backend = aco::BackendKind::automatic;  ///< backend running the ants
  std::size_t threads = 1;                                 ///< its threads; 0 = all cores

  /// MAX-MIN Ant System (25 ants and rho 0.2 with the local search); every variant reaches
  /// about the same clique on the consistency graphs (docs/robust-closures.md).
  static aco::Parameters default_parameters() {
    aco::Parameters p;
    p.variant = aco::Variant::mmas;
    return p;
  }
};

struct AcoSearchResult {
  CliqueResult clique;                                   ///< the best clique the ants built
  std::uint64_t iterations = 0;                          ///< colony iterations run
  aco::StopReason reason = aco::StopReason::iterations;  ///< why the run stopped
  std::uint64_t proof_nodes = 0;  ///< branch-and-bound nodes spent after the colony
};

/// Throws std::invalid_argument for an empty graph or invalid settings.
AcoSearchResult maximum_clique_aco(const Graph& graph, const AcoSearchSettings& settings = {});

}  // namespace antslam::clique
