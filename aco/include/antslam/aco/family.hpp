#pragma once
// Problem families: how an ant builds a solution of a problem and where its pheromone lives. The
// colony finds the family of a problem P through the trait family_of<P>, a customisation point:
// the engine's families (layered_family.hpp, permutation_family.hpp, subset_family.hpp) specialise
// it for the problems of their concept, and code outside the engine adds a family by defining a
// class that satisfies FamilyFor<F, P> and specialising the trait for its problems:
//
//   template <>
//   struct antslam::aco::family_of<MyProblem> {
//     using type = MyFamily<MyProblem>;
//   };
//
// (or a partial specialisation constrained by a concept of its own). The specialisation must be
// visible where the colony is instantiated, e.g. in the problem's header.

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "antslam/aco/chunked_for.hpp"
#include "antslam/aco/random.hpp"
#include "antslam/aco/rules.hpp"
#include "antslam/aco/update_context.hpp"

namespace antslam::aco {

/// The family of problem P: specialisations define `using type = ...;`.
template <class P>
struct family_of {};

template <class P>
concept HasFamily = requires {
  typename family_of<P>::type;
};

template <class P>
using family_t = typename family_of<P>::type;

/// What the pheromone-update policies (update_*.hpp) call on a family's trail. Deriving from
/// PheromoneValues (pheromone_values.hpp) gives fill, evaporate, clamp and values.
template <class T>
concept PheromoneTrail = requires(T& t, const T& ct, std::span<const std::uint32_t> path, double x,
                                  const ChunkedFor& parallel, void (*f)(double&)) {
  t.fill(x);
  t.evaporate(x, parallel);
  t.clamp(x, x, parallel);
  t.deposit(path, x, parallel);      // add x to every component of the path
  t.update_path(path, f, parallel);  // f(tau) on every component of the path, once each
  { ct.values() } -> std::convertible_to<std::span<const double>>;
  { ct.decision_count() } -> std::convertible_to<std::size_t>;  // decisions per solution
  { ct.mean_options() } -> std::convertible_to<double>;         // mean options per decision
  { ct.branching_factor(x) } -> std::convertible_to<double>;    // lambda-branching factor
  { T::converged_branching() } -> std::convertible_to<double>;  // its value once converged
};

/// A family F of problem P: what Colony (colony.hpp) calls. Required:
///   F(problem, alpha, beta)          built once per colony; keeps a pointer to the problem
///   Trail, trail()                   the pheromone (a PheromoneTrail)
///   reserve_ants(ants)               per-ant scratch memory
///   init_context(ants, local_search) the InitContext of the update's initialize (its
///                                    reference_cost: a greedy solution's cost, > 0)
///   prepare(rule)                    once per iteration, before the ants, after the update
///   construct(ant, path, rng, rule)  one ant's solution into path, drawing from rng only and
///                                    writing only ant's scratch (ants run in parallel)
/// Optional, found by the colony when present:
///   prepare(rule, backend)           prepare spread over the backend's threads
///   set_stop(stop)                   the run's stop token, for construction that polls it
///   construct_synchronous(rule, update, backend, ants, rngs)  the ants of an iteration with
///                                    Ant Colony System's local update (local_update(tau), in
///                                    ant order); needed by aco::solve, which offers every
///                                    variant (construct_then_local_update is the usual way)
///   set_source, focused, new_edges   focused construction (permutation_family.hpp)
///   static default_ants(problem)     ants per iteration when no variant or local search sets
///                                    them (the TSP: one per city); 20 without it
template <class F, class P>
concept FamilyFor = PheromoneTrail<typename F::Trail> &&
    std::constructible_from<F, const P&, double, double> &&
    requires(F& f, const F& cf, std::size_t n, bool b, std::vector<std::uint32_t>& path, Rng& rng,
             const RandomProportional& rule) {
  { f.trail() } -> std::same_as<typename F::Trail&>;
  { cf.trail() } -> std::same_as<const typename F::Trail&>;
  f.reserve_ants(n);
  { cf.init_context(n, b) } -> std::same_as<InitContext>;
  f.prepare(rule);
  f.construct(n, path, rng, rule);
};

/// P has a family and it is one.
template <class P>
concept FamilyOfProblem = HasFamily<P> && FamilyFor<family_t<P>, P>;

/// A family that says how many ants a colony on `problem` has by default.
template <class F, class P>
concept FamilyWithDefaultAnts = requires(const P& problem) {
  { F::default_ants(problem) } -> std::convertible_to<std::size_t>;
};

}  // namespace antslam::aco
