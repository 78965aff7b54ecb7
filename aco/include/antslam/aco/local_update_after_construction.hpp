#pragma once
// Ant Colony System's local update for families whose ants all build from the trail of the
// iteration's start (layered and subset problems): every ant is constructed in parallel, then
// the local update erodes the components of each path in ant order, so that the result does not
// depend on the thread count. (For a layered problem each layer is visited once per path, so
// this equals eroding after each synchronous step.)

#include <cstddef>
#include <span>

#include "antslam/aco/random.hpp"
#include "antslam/aco/solution.hpp"

namespace antslam::aco {

template <class Family, class Rule, class Update, class B>
void construct_then_local_update(Family& family, const Rule& rule, const Update& update, B& backend,
                                 std::span<Solution> ants, std::span<Rng> rngs) {
  backend.for_each(ants.size(),
                   [&](std::size_t a) { family.construct(a, ants[a].path, rngs[a], rule); });
  for (const Solution& ant : ants)
    family.trail().update_path(ant.path, [&](double& tau) { update.local_update(tau); });
}

}  // namespace antslam::aco
