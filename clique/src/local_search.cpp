#include "antslam/clique/local_search.hpp"

#include <algorithm>
#include <bit>
#include <initializer_list>

#include "bits.hpp"

namespace antslam::clique {

namespace {

/// Adds, lowest first, every vertex adjacent to the whole clique.
void make_maximal(const Graph& g, std::vector<std::uint32_t>& clique,
                  std::vector<std::uint64_t>& members) {
  detail::Bits open = detail::all_bits(g.size());
  for (const std::uint32_t v : clique) {
    const auto row = g.row(v);
    for (std::size_t k = 0; k < open.size(); ++k) open[k] &= row[k];
  }
  for (std::size_t k = 0; k < open.size(); ++k)
    while (open[k] != 0) {
      const auto u =
          static_cast<std::uint32_t>(k * 64 + static_cast<std::size_t>(std::countr_zero(open[k])));
      clique.push_back(u);
      detail::set_bit(members, u);
      const auto row = g.row(u);
      for (std::size_t j = k; j < open.size(); ++j) open[j] &= row[j];
    }
}

/// The 1-tight non-members of `members` and the member each one misses.
void find_one_tight(const Graph& g, SwapLocalSearch::Workspace& ws) {
  ws.tight.clear();
  ws.missing.clear();
  for (std::uint32_t u = 0; u < g.size(); ++u) {
    if (detail::test_bit(ws.members, u)) continue;
    const auto row = g.row(u);
    std::size_t misses = 0;
    std::uint32_t missed = 0;
    for (std::size_t k = 0; k < row.size() && misses < 2; ++k) {
      const std::uint64_t word = ws.members[k] & ~row[k];
      if (word == 0) continue;
      misses += static_cast<std::size_t>(std::popcount(word));
      missed =
          static_cast<std::uint32_t>(k * 64 + static_cast<std::size_t>(std::countr_zero(word)));
    }
    if (misses == 1) {
      ws.tight.push_back(u);
      ws.missing.push_back(missed);
    }
  }
}

/// Replaces member `out` by the non-members `in`, then makes the clique maximal again.
void swap_in(const Graph& g, std::vector<std::uint32_t>& clique,
             std::vector<std::uint64_t>& members, std::uint32_t out,
             std::initializer_list<std::uint32_t> in) {
  clique.erase(std::find(clique.begin(), clique.end(), out));
  detail::clear_bit(members, out);
  for (const std::uint32_t x : in) {
    clique.push_back(x);
    detail::set_bit(members, x);
  }
  make_maximal(g, clique, members);
}

/// (1,2)-swaps, the first gaining one in (v, u, w) order, until none gains or `stop` expires.
/// Unless stopped, ws.tight and ws.missing are left those of the clique it returns.
void ascend(const Graph& g, std::vector<std::uint32_t>& clique, SwapLocalSearch::Workspace& ws,
            const aco::StopToken& stop) {
  for (;;) {
    find_one_tight(g, ws);
    ws.order.resize(ws.tight.size());
    for (std::uint32_t i = 0; i < ws.order.size(); ++i) ws.order[i] = i;
    std::sort(ws.order.begin(), ws.order.end(), [&](std::uint32_t a, std::uint32_t b) {
      return ws.missing[a] < ws.missing[b] ||
             (ws.missing[a] == ws.missing[b] && ws.tight[a] < ws.tight[b]);
    });
    bool swapped = false;
    for (std::size_t first = 0; first < ws.order.size() && !swapped;) {
      std::size_t last = first;
      const std::uint32_t v = ws.missing[ws.order[first]];
      while (last < ws.order.size() && ws.missing[ws.order[last]] == v) ++last;
      for (std::size_t a = first; a < last && !swapped; ++a)
        for (std::size_t b = a + 1; b < last && !swapped; ++b) {
          const std::uint32_t u = ws.tight[ws.order[a]], w = ws.tight[ws.order[b]];
          if (g.adjacent(u, w) && g.weight(u) + g.weight(w) > g.weight(v)) {
            swap_in(g, clique, ws.members, v, {u, w});
            swapped = true;
          }
        }
      first = last;
    }
    if (!swapped || stop.expired()) return;
  }
}

}  // namespace

SwapLocalSearch::Workspace SwapLocalSearch::make_workspace(const CliqueProblem& problem) const {
  Workspace ws;
  ws.members.resize(problem.graph().words());
  return ws;
}

void SwapLocalSearch::improve(const CliqueProblem& problem, std::vector<std::uint32_t>& clique,
                              Workspace& ws, aco::Rng&, const aco::StopToken& stop) const {
  const Graph& g = problem.graph();
  std::fill(ws.members.begin(), ws.members.end(), 0);
  for (const std::uint32_t v : clique) detail::set_bit(ws.members, v);
  ascend(g, clique, ws, stop);
  if (plateau_steps == 0) return;
  ws.best = clique;
  double best_weight = weight_of(g, clique);
  ws.barred.assign(ws.members.size(), 0);
  for (std::size_t step = 0; step < plateau_steps && !stop.expired(); ++step) {
    std::size_t pick = 0;  // the lowest 1-tight vertex not barred and not lighter than its v
    while (pick < ws.tight.size() && (detail::test_bit(ws.barred, ws.tight[pick]) ||
                                      g.weight(ws.tight[pick]) < g.weight(ws.missing[pick])))
      ++pick;
    if (pick == ws.tight.size()) break;
    const std::uint32_t out = ws.missing[pick];
    detail::set_bit(ws.barred, out);
    swap_in(g, clique, ws.members, out, {ws.tight[pick]});
    ascend(g, clique, ws, stop);
    const double weight = weight_of(g, clique);
    if (weight > best_weight) {
      best_weight = weight;
      ws.best = clique;
    }
  }
  clique = ws.best;
}

}  // namespace antslam::clique
