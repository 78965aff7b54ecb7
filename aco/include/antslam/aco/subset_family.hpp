#pragma once
// Construction for subset-selection problems (Ant-Clique, Solnon & Fenet 2006, with vertex
// pheromone): an ant starts from the empty set and the full candidate set; it draws an element
// from the candidates with the construction rule over the weights tau_e^alpha eta_e^beta, takes
// it, and keeps only the candidates compatible with it; it stops when no candidate is left, so
// its set is maximal. The candidates stay in element order and are compacted without branches,
// in the same pass that adds up their weights for the next draw, so a step costs O(candidates).

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "antslam/aco/family.hpp"
#include "antslam/aco/local_update_after_construction.hpp"
#include "antslam/aco/problem.hpp"
#include "antslam/aco/random.hpp"
#include "antslam/aco/rules.hpp"
#include "antslam/aco/solution.hpp"
#include "antslam/aco/subset_trail.hpp"
#include "antslam/aco/update_context.hpp"

namespace antslam::aco {

template <SubsetProblem P>
class SubsetFamily {
 public:
  using Trail = SubsetTrail;

  SubsetFamily(const P& problem, double alpha, double beta)
      : problem_(&problem), alpha_(alpha), trail_(problem.element_count()) {
    const std::size_t n = trail_.element_count();
    eta_beta_.assign(n, 1.0);
    if constexpr (SubsetProblemWithHeuristic<P>) {
      for (std::uint32_t e = 0; e < n; ++e)
        eta_beta_[e] = std::pow(static_cast<double>(problem.heuristic(e)), beta);
    }
    weight_.assign(n, 0.0);
  }

  Trail& trail() { return trail_; }
  const Trail& trail() const { return trail_; }

  void reserve_ants(std::size_t ants) { scratch_.assign(ants, make_scratch()); }

  InitContext init_context(std::size_t ants, bool local_search) const {
    return {reference_cost(), ants, trail_.decision_count(), trail_.mean_options(), local_search};
  }

  /// Cost of the greedy set: the candidate with the largest heuristic at every step (lowest
  /// element on ties).
  double reference_cost() const {
    Scratch s = make_scratch();
    std::vector<std::uint32_t> subset;
    build(s, eta_beta_, subset, [](std::span<const double> w, double) {
      std::size_t best = 0;
      for (std::size_t r = 1; r < w.size(); ++r)
        if (w[r] > w[best]) best = r;
      return best;
    });
    const double cost = problem_->cost(subset);
    return cost > 0.0 ? cost : 1.0;
  }

  /// Weights tau^alpha eta^beta of every element for this iteration.
  template <class Rule>
  void prepare(const Rule&) {
    choice_weights(trail_.values(), alpha_, eta_beta_, weight_);
  }

  template <class Rule>
  void construct(std::size_t ant, std::vector<std::uint32_t>& subset, Rng& rng, const Rule& rule) {
    build(scratch_[ant], weight_, subset,
          [&](std::span<const double> w, double total) { return rule.choose(w, total, rng); });
  }

  /// Ant Colony System (local_update_after_construction.hpp).
  template <class Rule, class Update, class B>
  void construct_synchronous(const Rule& rule, const Update& update, B& backend,
                             std::span<Solution> ants, std::span<Rng> rngs) {
    construct_then_local_update(*this, rule, update, backend, ants, rngs);
  }

 private:
  /// Per-ant candidate list, a cache line of its own (ants on different threads write theirs at
  /// every step).
  struct alignas(64) Scratch {
    std::vector<std::uint32_t> element;  // the candidates, in element order
    std::vector<double> weight;          // their weights
  };

  Scratch make_scratch() const {
    Scratch s;
    s.element.resize(trail_.element_count());
    s.weight.resize(trail_.element_count());
    return s;
  }

  /// Builds a maximal set: pick(weights of the candidates, their sum) gives the index of the next
  /// element. The sum is accumulated in candidate order, as detail::sum would.
  template <class Pick>
  void build(Scratch& s, const std::vector<double>& weights, std::vector<std::uint32_t>& subset,
             Pick&& pick) const {
    std::size_t count = weights.size();
    double total = 0.0;
    for (std::uint32_t e = 0; e < count; ++e) {
      s.element[e] = e;
      s.weight[e] = weights[e];
      total += weights[e];
    }
    subset.clear();
    while (count > 0) {
      const std::uint32_t chosen =
          s.element[pick(std::span<const double>(s.weight.data(), count), total)];
      subset.push_back(chosen);
      std::size_t kept = 0;
      total = 0.0;
      for (std::size_t r = 0; r < count; ++r) {
        const std::uint32_t c = s.element[r];
        const double w = s.weight[r];
        const bool keep = c != chosen && problem_->compatible(chosen, c);
        s.element[kept] = c;
        s.weight[kept] = w;
        total += keep ? w : 0.0;
        kept += keep ? 1U : 0U;
      }
      count = kept;
    }
  }

  const P* problem_;
  double alpha_;
  SubsetTrail trail_;
  std::vector<double> eta_beta_;
  std::vector<double> weight_;
  std::vector<Scratch> scratch_;
};

template <SubsetProblem P>
struct family_of<P> {
  using type = SubsetFamily<P>;
};

}  // namespace antslam::aco
