#pragma once
// Construction for assignment problems (MMAS-QAP, Stuetzle & Hoos 2000, Sec. 5): n items go to n
// places, one item per place. An ant takes the items in a random order of its own and puts each
// at a free place drawn with the construction rule over the weights tau_il^alpha eta_il^beta of
// the pair (item i, place l); eta is 1 when the problem gives no heuristic (MMAS-QAP uses none).
// A step costs O(free places), an ant O(n^2).
//
// A family outside the colony's defaults: an assignment problem has size() and cost() only, which
// other concepts' problems have too, so a problem picks this family by specialising family_of
// (family.hpp), as qap/problem.hpp does:
//   template <> struct aco::family_of<MyProblem> { using type = AssignmentFamily<MyProblem>; };

#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "antslam/aco/assignment_trail.hpp"
#include "antslam/aco/family.hpp"
#include "antslam/aco/local_update_after_construction.hpp"
#include "antslam/aco/random.hpp"
#include "antslam/aco/rules.hpp"
#include "antslam/aco/solution.hpp"
#include "antslam/aco/update_context.hpp"

namespace antslam::aco {

/// Assignment problem: size() items, each to one of size() places, every place taken once; the
/// cost is a function of the assignment path (path[i] = place of item i), e.g. the QAP's.
template <class P>
concept AssignmentProblem = requires(const P& p, std::span<const std::uint32_t> assignment) {
  { p.size() } -> std::convertible_to<std::size_t>;
  { p.cost(assignment) } -> std::convertible_to<double>;
};

/// Optional heuristic desirability eta >= 0 of putting item i at place l (1 when absent).
template <class P>
concept AssignmentProblemWithHeuristic = AssignmentProblem<P> &&
    requires(const P& p, std::uint32_t i, std::uint32_t l) {
  { p.heuristic(i, l) } -> std::convertible_to<double>;
};

template <AssignmentProblem P>
class AssignmentFamily {
 public:
  using Trail = AssignmentTrail;

  AssignmentFamily(const P& problem, double alpha, double beta)
      : problem_(&problem), alpha_(alpha), trail_(problem.size()) {
    const std::size_t n = trail_.item_count();
    eta_beta_.assign(n * n, 1.0);
    if constexpr (AssignmentProblemWithHeuristic<P>) {
      for (std::uint32_t i = 0; i < n; ++i)
        for (std::uint32_t l = 0; l < n; ++l)
          eta_beta_[i * n + l] = std::pow(static_cast<double>(problem.heuristic(i, l)), beta);
    }
    weight_.assign(n * n, 0.0);
  }

  Trail& trail() { return trail_; }
  const Trail& trail() const { return trail_; }

  void reserve_ants(std::size_t ants) { scratch_.assign(ants, make_scratch()); }

  InitContext init_context(std::size_t ants, bool local_search) const {
    return {reference_cost(), ants, trail_.decision_count(), trail_.mean_options(), local_search};
  }

  /// Cost of the greedy assignment: items in index order, each at the free place of largest
  /// heuristic (lowest place on ties); without a heuristic, item i at place i.
  double reference_cost() const {
    const std::size_t n = trail_.item_count();
    std::vector<std::uint32_t> path(n);
    std::vector<std::uint8_t> taken(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      std::size_t best = n;
      for (std::size_t l = 0; l < n; ++l)
        if (taken[l] == 0 && (best == n || eta_beta_[i * n + l] > eta_beta_[i * n + best]))
          best = l;
      taken[best] = 1;
      path[i] = static_cast<std::uint32_t>(best);
    }
    const double cost = problem_->cost(path);
    return cost > 0.0 ? cost : 1.0;
  }

  /// Weights tau^alpha eta^beta of every pair for this iteration.
  template <class Rule>
  void prepare(const Rule&) {
    choice_weights(trail_.values(), alpha_, eta_beta_, weight_);
  }

  template <class Rule>
  void construct(std::size_t ant, std::vector<std::uint32_t>& path, Rng& rng, const Rule& rule) {
    const std::size_t n = trail_.item_count();
    Scratch& s = scratch_[ant];
    for (std::uint32_t i = 0; i < n; ++i) s.order[i] = s.place[i] = i;
    for (std::size_t k = n - 1; k > 0; --k)  // Fisher-Yates: the order the items are placed in
      std::swap(s.order[k], s.order[rng.below(static_cast<std::uint32_t>(k + 1))]);
    path.resize(n);
    std::size_t free = n;
    for (const std::uint32_t item : s.order) {
      const double* w = weight_.data() + std::size_t{item} * n;
      for (std::size_t r = 0; r < free; ++r) s.weight[r] = w[s.place[r]];
      const std::size_t r = rule.choose(std::span<const double>(s.weight.data(), free), rng);
      path[item] = s.place[r];
      s.place[r] = s.place[--free];
    }
  }

  /// Ant Colony System (local_update_after_construction.hpp).
  template <class Rule, class Update, class B>
  void construct_synchronous(const Rule& rule, const Update& update, B& backend,
                             std::span<Solution> ants, std::span<Rng> rngs) {
    construct_then_local_update(*this, rule, update, backend, ants, rngs);
  }

 private:
  /// Per-ant state, a cache line of its own (ants on different threads write theirs at every
  /// step).
  struct alignas(64) Scratch {
    std::vector<std::uint32_t> order;  // the items in the order they are placed
    std::vector<std::uint32_t> place;  // the free places first
    std::vector<double> weight;        // their weights for the current item
  };

  Scratch make_scratch() const {
    const std::size_t n = trail_.item_count();
    return {std::vector<std::uint32_t>(n), std::vector<std::uint32_t>(n), std::vector<double>(n)};
  }

  const P* problem_;
  double alpha_;
  AssignmentTrail trail_;
  std::vector<double> eta_beta_;
  std::vector<double> weight_;
  std::vector<Scratch> scratch_;
};

}  // namespace antslam::aco
