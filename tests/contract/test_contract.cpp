// The colony contract (colony_contract.hpp) on every real problem the project ships: the
// synthetic layered problem of the engine, the TSP without and with each local search, with
// both constructions (from nothing and focused), the AntSLAM problem of eq. (10) on the paper's
// N = 9 set, maximum weighted clique (the subset family) on a random graph, and the QAP (the
// assignment family, chosen outside the engine through aco::family_of).

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <span>
#include <vector>

#include "antslam/aco/synthetic_layered.hpp"
#include "antslam/clique/local_search.hpp"
#include "antslam/clique/problem.hpp"
#include "antslam/qap/local_search.hpp"
#include "antslam/qap/qaplib.hpp"
#include "antslam/slamgraph/slam_problem.hpp"
#include "antslam/slamgraph/synth.hpp"
#include "antslam/tsp/local_search.hpp"
#include "antslam/tsp/problem.hpp"
#include "antslam/tsp/tsplib.hpp"
#include "colony_contract.hpp"

namespace antslam {
namespace {

template <class Problem>
bool feasible_layered(const Problem& problem, std::span<const std::uint32_t> path) {
  if (path.size() != problem.layer_count()) return false;
  for (std::size_t l = 0; l < path.size(); ++l)
    if (path[l] >= problem.option_count(l)) return false;
  return true;
}

/// Whether path lists 0..n-1 once each.
bool is_permutation_of(std::span<const std::uint32_t> path, std::size_t n) {
  std::vector<std::uint32_t> identity(n);
  std::iota(identity.begin(), identity.end(), 0U);
  return std::is_permutation(path.begin(), path.end(), identity.begin(), identity.end());
}

struct SyntheticLayered {
  static constexpr std::size_t kIterations = 40;
  aco::SyntheticLayeredProblem p{8, 6, 17};
  const aco::SyntheticLayeredProblem& problem() const { return p; }
  aco::NoLocalSearch local_search() const { return {}; }
  bool feasible(std::span<const std::uint32_t> path) const { return feasible_layered(p, path); }
};

/// att48 (TSPLIB, ATT distances), 8 candidates per city, with local search `Kind`.
template <tsp::LocalSearchKind Kind>
struct Tsp {
  static constexpr std::size_t kIterations = 20;
  static const tsp::TspProblem& shared() {
    static const tsp::TspProblem p(tsp::read_instance(ANTSLAM_TSP_FIXTURES "/att48.tsp"),
                                   tsp::ProblemSettings{.candidates = 8, .ls_neighbours = 8});
    return p;
  }
  const tsp::TspProblem& problem() const { return shared(); }
  auto local_search() const {
    if constexpr (Kind == tsp::LocalSearchKind::none) {
      return aco::NoLocalSearch{};
    } else {
      return tsp::TourLocalSearch({.kind = Kind, .neighbours = 8});
    }
  }
  bool feasible(std::span<const std::uint32_t> tour) const {
    return is_permutation_of(tour, shared().size());
  }
};

/// The same with focused construction: from the second iteration ants change a source tour (the
/// best-so-far one in a third of the iterations) in at least 3 edges.
template <tsp::LocalSearchKind Kind>
struct TspFocused : Tsp<Kind> {
  static void configure(aco::Parameters& p) {
    p.focused = {.min_new_edges = 3, .global_best_source = 0.3};
  }
};

/// The AntSLAM problem (eq. 10) on the paper's N = 9 synthetic set, M = 20 samples.
struct Slam {
  static constexpr std::size_t kIterations = 40;
  static const slam::SlamProblem& shared() {
    static const slam::FragmentSet set = slam::synthesize(slam::synth_preset("paper9"));
    static const slam::SlamProblem p(set);
    return p;
  }
  const slam::SlamProblem& problem() const { return shared(); }
  aco::NoLocalSearch local_search() const { return {}; }
  bool feasible(std::span<const std::uint32_t> path) const {
    return feasible_layered(shared(), path);
  }
};

/// Maximum weighted clique on G(60, 0.5) with weights 1..4, without or with the (1,2)-swap
/// local search: a set is feasible when it is a maximal clique (the construction stops only
/// when no candidate is left, and the swaps keep it maximal).
template <bool kSwaps>
struct Clique {
  static constexpr std::size_t kIterations = 30;
  static const clique::Graph& graph() {
    static const clique::Graph g = [] {
      aco::Rng rng(aco::mix_seed(2018, 0xC1));
      std::vector<clique::Edge> edges;
      for (std::uint32_t i = 0; i < 60; ++i)
        for (std::uint32_t j = i + 1; j < 60; ++j)
          if (rng.uniform() < 0.5) edges.emplace_back(i, j);
      std::vector<double> weights;
      for (int v = 0; v < 60; ++v) weights.push_back(1.0 + rng.below(4));
      return clique::Graph(60, edges, weights);
    }();
    return g;
  }
  static const clique::CliqueProblem& shared() {
    static const clique::CliqueProblem p(graph());
    return p;
  }
  const clique::CliqueProblem& problem() const { return shared(); }
  auto local_search() const {
    if constexpr (kSwaps) {
      return clique::SwapLocalSearch{};
    } else {
      return aco::NoLocalSearch{};
    }
  }
  bool feasible(std::span<const std::uint32_t> set) const {
    return clique::is_maximal_clique(graph(), set);
  }
};

/// tai12a (QAPLIB), without or with the pair-swap local search: an assignment is feasible when
/// it puts the 12 facilities at 12 distinct locations.
template <bool kPairSwap>
struct Qap {
  static constexpr std::size_t kIterations = 20;
  static const qap::QapProblem& shared() {
    static const qap::QapProblem p(qap::read_qaplib(ANTSLAM_DATA_DIR "/qaplib/tai12a.dat"));
    return p;
  }
  const qap::QapProblem& problem() const { return shared(); }
  auto local_search() const {
    if constexpr (kPairSwap) {
      return qap::PairSwapLocalSearch{};
    } else {
      return aco::NoLocalSearch{};
    }
  }
  bool feasible(std::span<const std::uint32_t> assignment) const {
    return is_permutation_of(assignment, shared().size());
  }
};

using TspNoLocalSearch = Tsp<tsp::LocalSearchKind::none>;
using TspTwoOpt = Tsp<tsp::LocalSearchKind::two_opt>;
using TspTwoHalfOpt = Tsp<tsp::LocalSearchKind::two_half_opt>;
using TspThreeOpt = Tsp<tsp::LocalSearchKind::three_opt>;
using TspFocusedNoLocalSearch = TspFocused<tsp::LocalSearchKind::none>;
using TspFocusedThreeOpt = TspFocused<tsp::LocalSearchKind::three_opt>;

ANTSLAM_COLONY_CONTRACT(SyntheticLayered, SyntheticLayered);
ANTSLAM_COLONY_CONTRACT(TspNoLocalSearch, TspNoLocalSearch);
ANTSLAM_COLONY_CONTRACT(TspTwoOpt, TspTwoOpt);
ANTSLAM_COLONY_CONTRACT(TspTwoHalfOpt, TspTwoHalfOpt);
ANTSLAM_COLONY_CONTRACT(TspThreeOpt, TspThreeOpt);
ANTSLAM_COLONY_CONTRACT(TspFocusedNoLocalSearch, TspFocusedNoLocalSearch);
ANTSLAM_COLONY_CONTRACT(TspFocusedThreeOpt, TspFocusedThreeOpt);
ANTSLAM_COLONY_CONTRACT(Slam, Slam);
using CliqueNoLocalSearch = Clique<false>;
using CliqueSwaps = Clique<true>;

ANTSLAM_COLONY_CONTRACT(CliqueNoLocalSearch, CliqueNoLocalSearch);
ANTSLAM_COLONY_CONTRACT(CliqueSwaps, CliqueSwaps);

using QapNoLocalSearch = Qap<false>;
using QapPairSwap = Qap<true>;

ANTSLAM_COLONY_CONTRACT(QapNoLocalSearch, QapNoLocalSearch);
ANTSLAM_COLONY_CONTRACT(QapPairSwap, QapPairSwap);

}  // namespace
}  // namespace antslam
