// Families are open: a family defined here, outside the engine, plugs into Colony and
// aco::solve through aco::family_of alone.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "antslam/aco/colony.hpp"
#include "antslam/aco/family.hpp"
#include "antslam/aco/local_update_after_construction.hpp"
#include "antslam/aco/pheromone_values.hpp"
#include "antslam/aco/synthetic_layered.hpp"
#include "antslam/aco/update_mmas.hpp"
#include "antslam/aco/variants.hpp"

namespace antslam::aco {
namespace {

/// A bit string; its cost is the number of bits that differ from a hidden pattern.
struct BitsProblem {
  std::vector<std::uint32_t> pattern;
  double cost(std::span<const std::uint32_t> bits) const {
    double differ = 0.0;
    for (std::size_t i = 0; i < bits.size(); ++i) differ += bits[i] != pattern[i] ? 1.0 : 0.0;
    return differ;
  }
};

/// Pheromone tau[2 i + v] on bit i taking value v.
class BitTrail : public PheromoneValues {
 public:
  explicit BitTrail(std::size_t bits) : PheromoneValues(2 * bits) {}
  template <class F>
  void update_path(std::span<const std::uint32_t> bits, F&& f, const ChunkedFor& = {}) {
    for (std::size_t i = 0; i < bits.size(); ++i) f(tau_[2 * i + bits[i]]);
  }
  void deposit(std::span<const std::uint32_t> bits, double amount, const ChunkedFor& = {}) {
    update_path(bits, [amount](double& t) { t += amount; });
  }
  std::size_t decision_count() const { return tau_.size() / 2; }
  static double mean_options() { return 2.0; }
  double branching_factor(double lambda) const {
    double total = 0.0;
    for (std::size_t i = 0; i < tau_.size(); i += 2)
      total += branches(std::span<const double>(tau_).subspan(i, 2), lambda);
    return total / static_cast<double>(decision_count());
  }
  static constexpr double converged_branching() { return 1.0; }
};

/// Each bit drawn with the rule over its two pheromone values.
class BitFamily {
 public:
  using Trail = BitTrail;
  BitFamily(const BitsProblem& problem, double, double)
      : problem_(&problem), trail_(problem.pattern.size()) {}
  Trail& trail() { return trail_; }
  const Trail& trail() const { return trail_; }
  void reserve_ants(std::size_t) {}
  InitContext init_context(std::size_t ants, bool local_search) const {
    const std::vector<std::uint32_t> zeros(problem_->pattern.size(), 0);
    return {std::max(problem_->cost(zeros), 1.0), ants, trail_.decision_count(), 2.0, local_search};
  }
  template <class Rule>
  void prepare(const Rule&) {}
  template <class Rule>
  void construct(std::size_t, std::vector<std::uint32_t>& bits, Rng& rng, const Rule& rule) {
    bits.resize(problem_->pattern.size());
    for (std::size_t i = 0; i < bits.size(); ++i)
      bits[i] = static_cast<std::uint32_t>(rule.choose(trail_.values().subspan(2 * i, 2), rng));
  }
  template <class Rule, class Update, class B>
  void construct_synchronous(const Rule& rule, const Update& update, B& backend,
                             std::span<Solution> ants, std::span<Rng> rngs) {
    construct_then_local_update(*this, rule, update, backend, ants, rngs);
  }

 private:
  const BitsProblem* problem_;
  BitTrail trail_;
};

}  // namespace

template <>
struct family_of<BitsProblem> {
  using type = BitFamily;
};

namespace {

static_assert(FamilyFor<BitFamily, BitsProblem>);
static_assert(HasFamily<BitsProblem>);
static_assert(!HasFamily<int>);
static_assert(FamilyOfProblem<SyntheticLayeredProblem>);

TEST(OpenFamily, AColonyOfAFamilyDefinedOutsideTheEngineRuns) {
  const BitsProblem problem{{1, 0, 1, 1, 0, 0, 1, 0, 1, 1, 1, 0}};
  Colony<BitsProblem, RandomProportional, MaxMinUpdate> colony(problem, {.ants = 10, .seed = 3}, {},
                                                               MaxMinUpdate());
  const RunResult r = colony.run({.max_iterations = 500, .target_cost = 0.0});
  EXPECT_EQ(r.best.path, problem.pattern);
  EXPECT_EQ(r.reason, StopReason::target);
}

TEST(OpenFamily, EveryVariantSolvesIt) {
  const BitsProblem problem{{0, 1, 1, 0, 1, 0}};
  for (Variant v : all_variants()) {
    Parameters p;
    p.variant = v;
    const RunResult r = solve(problem, p, {.max_iterations = 300, .target_cost = 0.0});
    EXPECT_EQ(r.best.cost, 0.0) << to_string(v);
  }
}

}  // namespace
}  // namespace antslam::aco
