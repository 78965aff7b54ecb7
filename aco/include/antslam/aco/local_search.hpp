#pragma once
// Local-search policy: improves an ant's path after construction (Algorithm 1, line 4).
// A policy provides a per-ant Workspace (scratch memory reused across iterations) and
//   improve(problem, path, workspace, rng, stop)
// which must keep the path feasible and must never make it worse.

#include <concepts>
#include <cstdint>
#include <span>
#include <vector>

#include "antslam/aco/random.hpp"
#include "antslam/aco/termination.hpp"

namespace antslam::aco {

template <class LS, class P>
concept LocalSearchFor = requires(const LS& ls, const P& p, typename LS::Workspace& ws,
                                  std::vector<std::uint32_t>& path, Rng& rng,
                                  const StopToken& stop) {
  { ls.make_workspace(p) } -> std::same_as<typename LS::Workspace>;
  ls.improve(p, path, ws, rng, stop);
};

/// Optional: a local search that starts from given cities only,
///   improve(problem, path, workspace, rng, stop, new_edges)
/// where new_edges lists city pairs (a, b): the edges of `path` that are not in a tour the
/// search left locally optimal (the source of a focused construction). Every other city is taken
/// as already improved, as with don't-look bits.
template <class LS, class P>
concept LocalSearchFromCities = LocalSearchFor<LS, P> &&
    requires(const LS& ls, const P& p, typename LS::Workspace& ws, std::vector<std::uint32_t>& path,
             Rng& rng, const StopToken& stop, std::span<const std::uint32_t> edges) {
  ls.improve(p, path, ws, rng, stop, edges);
};

/// No local search.
struct NoLocalSearch {
  struct Workspace {};
  template <class P>
  Workspace make_workspace(const P&) const {
    return {};
  }
  template <class P>
  void improve(const P&, std::vector<std::uint32_t>&, Workspace&, Rng&, const StopToken&) const {}
};

}  // namespace antslam::aco
