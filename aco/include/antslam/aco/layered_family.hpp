#pragma once
// Construction for layered-choice problems. The pheromone does not change while the ants of one
// iteration build their paths, so the rule's probabilities of every layer are turned into a
// cumulative table once per iteration; an ant then draws each option with one uniform number
// and a branch-free count (this is what makes 3000 x 20 AntSLAM ants take milliseconds).

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "antslam/aco/family.hpp"
#include "antslam/aco/layered_trail.hpp"
#include "antslam/aco/local_update_after_construction.hpp"
#include "antslam/aco/problem.hpp"
#include "antslam/aco/random.hpp"
#include "antslam/aco/rules.hpp"
#include "antslam/aco/update_context.hpp"

namespace antslam::aco {

template <LayeredProblem P>
class LayeredFamily {
 public:
  using Trail = LayeredTrail;

  LayeredFamily(const P& problem, double alpha, double beta) : problem_(&problem), alpha_(alpha) {
    std::vector<std::size_t> counts(problem.layer_count());
    for (std::size_t l = 0; l < counts.size(); ++l) counts[l] = problem.option_count(l);
    trail_ = LayeredTrail(counts);
    const std::size_t total = trail_.values().size();
    eta_beta_.assign(total, 1.0);
    if constexpr (LayeredProblemWithHeuristic<P>) {
      for (std::size_t l = 0; l < counts.size(); ++l)
        for (std::size_t o = 0; o < counts[l]; ++o)
          eta_beta_[trail_.offset(l) + o] = std::pow(problem.heuristic(l, o), beta);
    }
    cdf_.assign(total, 0.0);
    weight_.assign(total, 0.0);
    probability_.assign(total, 0.0);
  }

  Trail& trail() { return trail_; }
  const Trail& trail() const { return trail_; }
  void reserve_ants(std::size_t) {}
  std::size_t path_length() const { return trail_.layer_count(); }

  InitContext init_context(std::size_t ants, bool local_search) const {
    return {reference_cost(), ants, trail_.decision_count(), trail_.mean_options(), local_search};
  }

  /// Cost of the greedy path (best heuristic option of every layer, lowest index on ties).
  double reference_cost() const {
    std::vector<std::uint32_t> path(trail_.layer_count());
    for (std::size_t l = 0; l < path.size(); ++l) {
      std::size_t best = 0;
      for (std::size_t o = 1; o < trail_.option_count(l); ++o)
        if (eta_beta_[trail_.offset(l) + o] > eta_beta_[trail_.offset(l) + best]) best = o;
      path[l] = static_cast<std::uint32_t>(best);
    }
    const double cost = problem_->cost(path);
    return cost > 0.0 ? cost : 1.0;
  }

  /// Builds the cumulative sampling table of every layer for this iteration.
  template <class Rule>
  void prepare(const Rule& rule) {
    choice_weights(trail_.values(), alpha_, eta_beta_, weight_);
    for (std::size_t l = 0; l < trail_.layer_count(); ++l) {
      const std::size_t begin = trail_.offset(l);
      const std::size_t m = trail_.option_count(l);
      rule.distribution({weight_.data() + begin, m}, {probability_.data() + begin, m});
      double acc = 0.0;
      std::size_t last_positive = 0;
      for (std::size_t o = 0; o < m; ++o) {
        acc += probability_[begin + o];
        cdf_[begin + o] = acc;
        if (probability_[begin + o] > 0.0) last_positive = o;
      }
      // Options from the last one with positive probability on can never be overshot.
      for (std::size_t o = last_positive; o < m; ++o)
        cdf_[begin + o] = std::numeric_limits<double>::infinity();
    }
  }

  /// One ant's path: option of layer l = number of cumulative entries <= u.
  template <class Rule>
  void construct(std::size_t, std::vector<std::uint32_t>& path, Rng& rng, const Rule&) const {
    const std::size_t layers = trail_.layer_count();
    path.resize(layers);
    for (std::size_t l = 0; l < layers; ++l) {
      const double u = rng.uniform();
      path[l] = count_at_most(cdf_.data() + trail_.offset(l), trail_.option_count(l), u);
    }
  }

  /// Number of entries <= u of the non-decreasing cdf[0..m), m >= 1: a branch-free binary
  /// search, log2 m dependent loads instead of m compares. (Written as a select on indices,
  /// which compilers turn into a conditional move; u is random, so a branch would be
  /// mispredicted half the time.)
  static std::uint32_t count_at_most(const double* cdf, std::size_t m, double u) {
    std::size_t low = 0;  // cdf[0..low) are all <= u
    for (std::size_t n = m; n > 1;) {
      const std::size_t half = n / 2;
      const std::size_t next = low + half;
      low = cdf[next - 1] <= u ? next : low;
      n -= half;
    }
    return static_cast<std::uint32_t>(low) + (cdf[low] <= u ? 1U : 0U);
  }

  /// Ant Colony System (local_update_after_construction.hpp).
  template <class Rule, class Update, class B>
  void construct_synchronous(const Rule& rule, const Update& update, B& backend,
                             std::span<Solution> ants, std::span<Rng> rngs) {
    construct_then_local_update(*this, rule, update, backend, ants, rngs);
  }

 private:
  const P* problem_;
  double alpha_;
  LayeredTrail trail_;
  std::vector<double> eta_beta_;
  std::vector<double> weight_;
  std::vector<double> probability_;
  std::vector<double> cdf_;
};

template <LayeredProblem P>
struct family_of<P> {
  using type = LayeredFamily<P>;
};

}  // namespace antslam::aco
