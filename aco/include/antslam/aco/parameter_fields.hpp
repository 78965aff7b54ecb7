#pragma once
// The numbers of aco::Parameters by name, for the result files that record what ran (the
// variant, the seed, the local-search share and the focused construction are recorded by
// each file as it names them).

#include <concepts>
#include <type_traits>

#include "antslam/aco/variants.hpp"

namespace antslam::aco {

/// Calls visit(name, field) for every number of `p` below, in this order; field is a reference
/// to the member (const when `p` is).
template <class P, class Visit>
requires std::same_as<std::remove_const_t<P>, Parameters>
void for_each_parameter(P& p, Visit&& visit) {
  visit("ants", p.ants);
  visit("alpha", p.alpha);
  visit("beta", p.beta);
  visit("rho", p.rho);
  visit("q0", p.q0);
  visit("xi", p.xi);
  visit("elite_weight", p.elite_weight);
  visit("rank_width", p.rank_width);
  visit("p_best", p.p_best);
  visit("restarts", p.restarts);
  visit("restart_stagnant", p.restart_stagnant);
  visit("p0", p.p0);
  visit("glob_best_freq", p.glob_best_freq);
  visit("tau_max", p.tau_max);
  visit("tau_init", p.tau_init);
  visit("hybrid_deposit", p.hybrid_deposit);
}

}  // namespace antslam::aco
