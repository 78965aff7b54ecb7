#pragma once
// Construction for symmetric permutation problems (TSP). An ant starts at a random node and
// repeatedly picks, with the construction rule, among the unvisited nodes of its current node's
// candidate list; when all candidates are visited it moves to the nearest unvisited node (as
// ACOTSP's neighbour_choose_and_move_to_next, with distance as the fallback criterion). So a
// tour costs O(n k) plus the fallbacks, each an O(n) scan -- or, for problems that offer one
// (PermutationProblemWithNearestSearch), an exact search that is about O(1) per fallback.
// Once the colony gives it a source tour (set_source), ants change that tour instead of building
// from nothing: focused construction (focused_construction.hpp). Once the run's stop token
// expires (set_stop), a tour under construction is finished by appending its unvisited nodes in
// index order, O(n): on a million nodes one ant takes seconds, and a budget must hold inside an
// iteration.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

#include "antslam/aco/backend.hpp"
#include "antslam/aco/edge_trail.hpp"
#include "antslam/aco/family.hpp"
#include "antslam/aco/focused_construction.hpp"
#include "antslam/aco/problem.hpp"
#include "antslam/aco/random.hpp"
#include "antslam/aco/rules.hpp"
#include "antslam/aco/termination.hpp"
#include "antslam/aco/update_context.hpp"

namespace antslam::aco {

namespace detail {
struct NoNearestSearch {};
template <class P>
struct NearestSearchOf {
  using type = NoNearestSearch;
};
template <PermutationProblemWithNearestSearch P>
struct NearestSearchOf<P> {
  using type = decltype(std::declval<const P&>().make_nearest_search());
};
}  // namespace detail

template <PermutationProblem P>
class PermutationFamily {
 public:
  using Trail = EdgeTrail;

  PermutationFamily(const P& problem, double alpha, double beta) : PermutationFamily(problem) {
    alpha_ = alpha;
    std::vector<std::uint32_t> neighbours;
    neighbours.reserve(std::size_t{n_} * k_);
    for (std::uint32_t i = 0; i < n_; ++i) {
      const std::span<const std::uint32_t> list = problem.candidates(i);
      if (list.size() != k_)
        throw std::invalid_argument("permutation problem: candidate lists differ in length");
      neighbours.insert(neighbours.end(), list.begin(), list.end());
    }
    trail_ = EdgeTrail(n_, k_, std::move(neighbours));
    eta_beta_.resize(std::size_t{n_} * k_);
    for (std::uint32_t i = 0; i < n_; ++i) {
      const auto list = trail_.neighbours(i);
      for (std::size_t r = 0; r < k_; ++r)
        eta_beta_[std::size_t{i} * k_ + r] = std::pow(heuristic(i, list[r]), beta);
    }
    weight_.assign(eta_beta_.size(), 0.0);
  }

  Trail& trail() { return trail_; }
  const Trail& trail() const { return trail_; }
  std::size_t path_length() const { return n_; }

  /// One ant per city without local search (Dorigo & Stuetzle 2004, Table 3.3).
  static std::size_t default_ants(const P& problem) { return problem.size(); }

  void reserve_ants(std::size_t ants) {
    scratch_.clear();
    for (std::size_t a = 0; a < ants; ++a) scratch_.push_back(make_scratch());
  }

  InitContext init_context(std::size_t ants, bool local_search) const {
    return {reference_cost(), ants,  trail_.decision_count(), trail_.mean_options(),
            local_search,     false, static_cast<double>(k_)};
  }

  /// From now on ants change `tour` and add at least `min_new_edges` edges of their own
  /// (focused construction); min_new_edges = 0 returns to building tours from nothing.
  void set_source(std::span<const std::uint32_t> tour, std::size_t min_new_edges) {
    min_new_edges_ = min_new_edges;
    if (min_new_edges_ > 0) source_.assign(tour);
  }
  bool focused() const { return min_new_edges_ > 0; }
  /// The edges of ant `ant`'s last focused tour that are not in the source, as city pairs.
  std::span<const std::uint32_t> new_edges(std::size_t ant) const {
    return scratch_[ant].new_edges;
  }

  /// C_nn: length of the nearest-neighbour tour from node 0.
  double reference_cost() const {
    Scratch s = make_scratch();
    std::vector<std::uint32_t> tour;
    std::uint32_t* t = begin(s, tour, 0);
    for (std::uint32_t step = 1; step < n_; ++step) {
      std::uint32_t next = kNone;
      for (std::uint32_t j : problem_->candidates(t[step - 1]))
        if (!s.visited[j]) {
          next = j;
          break;
        }
      visit(s, t, next == kNone ? nearest_unvisited(s, t[step - 1]) : next);
    }
    return problem_->cost(tour);
  }

  /// reference_cost() without building the trail: the heuristic values and the trail's mirror
  /// indices of a million nodes take seconds, wasted on a caller that needs only C_nn.
  static double nearest_neighbour_cost(const P& problem) {
    return PermutationFamily(problem).reference_cost();
  }

  /// Weights tau^alpha eta^beta of every candidate edge (ACOTSP's "total" matrix), in blocks
  /// spread over the backend's threads when there is more than one block (serial without one).
  template <class Rule>
  void prepare(const Rule& rule) {
    SerialBackend serial;
    prepare(rule, serial);
  }
  template <class Rule, class B>
  void prepare(const Rule&, B& backend) {
    constexpr std::size_t kBlock = 1 << 15;
    const auto tau = trail_.values();
    const std::size_t blocks = (weight_.size() + kBlock - 1) / kBlock;
    const auto refresh_block = [&](std::size_t b) {
      const std::size_t end = std::min(weight_.size(), (b + 1) * kBlock);
      for (std::size_t e = b * kBlock; e < end; ++e) refresh(e, tau[e]);
    };
    if (blocks <= 1) {
      refresh_block(0);
    } else {
      backend.for_each(blocks, refresh_block);
    }
  }

  /// The token construct() and construct_synchronous() poll (every kStopPoll steps).
  void set_stop(const StopToken& stop) { stop_ = stop; }

  template <class Rule>
  void construct(std::size_t ant, std::vector<std::uint32_t>& tour, Rng& rng, const Rule& rule) {
    Scratch& s = scratch_[ant];
    Rng local = rng;  // the colony's generators sit side by side: keep this one's in a register
    const std::uint32_t start = local.below(n_);
    if (focused()) {
      std::uint32_t* t = clear(s, tour);
      build_focused(
          source_, n_, start, min_new_edges_,
          [&](std::uint32_t current) { return choose_next(s, current, local, rule); },
          [&](std::uint32_t city) { visit(s, t, city); },
          [&](std::uint32_t city) { return s.visited[city] != 0; }, s.new_edges);
    } else {
      std::uint32_t* t = begin(s, tour, start);
      for (std::uint32_t step = 1; step < n_; ++step) {
        if (step % kStopPoll == 0 && stop_.expired()) {
          complete(s, t);
          break;
        }
        visit(s, t, choose_next(s, t[step - 1], local, rule));
      }
    }
    rng = local;
  }

  /// Ant Colony System: all ants move one step, then apply the local update in ant order
  /// (Dorigo & Gambardella 1997 move ants synchronously), so results are thread-independent.
  /// Focused ants build their tours independently; the local update then erodes the edges each
  /// ant added (its new edges), in ant order.
  template <class Rule, class Update, class B>
  void construct_synchronous(const Rule& rule, const Update& update, B& backend,
                             std::span<Solution> ants, std::span<Rng> rngs) {
    const auto local = [&](std::uint32_t i, std::uint32_t j) {
      const std::uint32_t e =
          trail_.update_edge(i, j, [&](double& tau) { update.local_update(tau); });
      if (e != EdgeTrail::kNone) {
        refresh(e, trail_.entry(e));
        if (trail_.mirror(e) != EdgeTrail::kNone) refresh(trail_.mirror(e), trail_.entry(e));
      }
    };
    if (focused()) {
      backend.for_each(ants.size(),
                       [&](std::size_t a) { construct(a, ants[a].path, rngs[a], rule); });
      for (std::size_t a = 0; a < ants.size(); ++a) {
        const std::vector<std::uint32_t>& added = scratch_[a].new_edges;
        for (std::size_t e = 0; e < added.size(); e += 2) local(added[e], added[e + 1]);
      }
      return;
    }
    for (std::size_t a = 0; a < ants.size(); ++a)
      begin(scratch_[a], ants[a].path, rngs[a].below(n_));
    for (std::uint32_t step = 1; step < n_; ++step) {
      if (step % kStopPoll == 0 && stop_.expired()) {
        for (std::size_t a = 0; a < ants.size(); ++a) complete(scratch_[a], ants[a].path.data());
        return;
      }
      backend.for_each(ants.size(), [&](std::size_t a) {
        std::uint32_t* t = ants[a].path.data();
        visit(scratch_[a], t, choose_next(scratch_[a], t[step - 1], rngs[a], rule));
      });
      for (const Solution& ant : ants) local(ant.path[step - 1], ant.path[step]);
    }
    for (const Solution& ant : ants) local(ant.path.back(), ant.path.front());
  }

 private:
  /// The problem and its sizes only, no trail: enough for reference_cost().
  explicit PermutationFamily(const P& problem)
      : problem_(&problem), n_(static_cast<std::uint32_t>(problem.size())) {
    if (n_ < 3) throw std::invalid_argument("permutation problem needs at least 3 nodes");
    k_ = problem.candidates(0).size();
    if (k_ == 0) throw std::invalid_argument("permutation problem has empty candidate lists");
  }

  static constexpr std::uint32_t kNone = EdgeTrail::kNone;
  static constexpr std::uint32_t kStopPoll = 1024;  ///< steps between looks at the stop token
  static constexpr bool kHasNearestSearch = PermutationProblemWithNearestSearch<P>;
  using NearestSearch = typename detail::NearestSearchOf<P>::type;

  /// Per-ant state, a cache line of its own: ants on different threads write theirs at every
  /// step, and sharing a line would make the cores fight over it.
  struct alignas(64) Scratch {
    std::vector<std::uint8_t> visited;
    std::vector<std::uint32_t> unvisited;  // compact list of unvisited nodes (scan fallback)
    std::vector<std::uint32_t> slot;       // position of a node in `unvisited`
    std::uint32_t remaining = 0;
    std::uint32_t length = 0;                    // cities placed in the tour so far
    std::vector<double> weight;                  // weights of the feasible candidates
    std::vector<std::uint32_t> node;             // the feasible candidates
    std::vector<std::uint32_t> new_edges;        // focused construction: edges not in the source
    [[no_unique_address]] NearestSearch search;  // the problem's fallback search, if any
  };

  Scratch make_scratch() const {
    Scratch s;
    s.visited.assign(n_, 0);
    s.weight.resize(k_);
    s.node.resize(k_);
    if constexpr (kHasNearestSearch) {
      s.search = problem_->make_nearest_search();
    } else {
      s.unvisited.resize(n_);
      s.slot.resize(n_);
    }
    return s;
  }

  double heuristic(std::uint32_t i, std::uint32_t j) const {
    if constexpr (PermutationProblemWithHeuristic<P>) {
      return problem_->heuristic(i, j);
    } else {
      return 1.0 / (static_cast<double>(problem_->distance(i, j)) + 0.1);
    }
  }

  void refresh(std::size_t e, double tau) { weight_[e] = choice_weight(tau, alpha_, eta_beta_[e]); }

  /// Starts a tour at `start`; returns where its cities go (the vector is sized once, so that
  /// steps write only to its buffer, never to the vector itself).
  std::uint32_t* begin(Scratch& s, std::vector<std::uint32_t>& tour, std::uint32_t start) const {
    std::uint32_t* t = clear(s, tour);
    visit(s, t, start);
    return t;
  }

  /// An empty tour: every city unvisited.
  std::uint32_t* clear(Scratch& s, std::vector<std::uint32_t>& tour) const {
    std::fill(s.visited.begin(), s.visited.end(), 0);
    if constexpr (kHasNearestSearch) {
      s.search.reset();
    } else {
      for (std::uint32_t i = 0; i < n_; ++i) s.unvisited[i] = s.slot[i] = i;
      s.remaining = n_;
    }
    tour.resize(n_);
    s.length = 0;
    return tour.data();
  }

  static void visit(Scratch& s, std::uint32_t* tour, std::uint32_t node) {
    tour[s.length++] = node;
    s.visited[node] = 1;
    if constexpr (kHasNearestSearch) {
      s.search.remove(node);
    } else {
      const std::uint32_t last = s.unvisited[--s.remaining];
      s.unvisited[s.slot[node]] = last;
      s.slot[last] = s.slot[node];
    }
  }

  /// Appends the unvisited nodes in index order: a valid tour at once when time is up. The tour
  /// is finished, so the nearest-unvisited search is not told (clear() resets it for the next
  /// tour): removing a million nodes from it, for every ant Ant Colony System moves in step,
  /// took half a second past the budget.
  void complete(Scratch& s, std::uint32_t* tour) const {
    for (std::uint32_t i = 0; i < n_ && s.length < n_; ++i)
      if (s.visited[i] == 0) {
        tour[s.length++] = i;
        s.visited[i] = 1;
      }
  }

  template <class Rule>
  std::uint32_t choose_next(Scratch& s, std::uint32_t current, Rng& rng, const Rule& rule) const {
    const std::uint32_t* list = trail_.neighbours(current).data();
    const double* w = weight_.data() + std::size_t{current} * k_;
    const std::uint8_t* visited = s.visited.data();
    double* weight = s.weight.data();
    std::uint32_t* node = s.node.data();
    std::size_t feasible = 0;
    for (std::size_t r = 0; r < k_; ++r) {  // branch-free compaction of the unvisited candidates
      weight[feasible] = w[r];
      node[feasible] = list[r];
      feasible += visited[list[r]] == 0 ? 1 : 0;
    }
    if (feasible == 0) return nearest_unvisited(s, current);
    return node[rule.choose(std::span<const double>(weight, feasible), rng)];
  }

  /// Fallback when every candidate is visited: the nearest unvisited node (lowest id on ties).
  std::uint32_t nearest_unvisited(Scratch& s, std::uint32_t current) const {
    if constexpr (kHasNearestSearch) {
      return s.search.nearest(current);
    } else {
      std::uint32_t best = kNone;
      double best_d = std::numeric_limits<double>::infinity();
      for (std::uint32_t r = 0; r < s.remaining; ++r) {
        const std::uint32_t j = s.unvisited[r];
        const auto d = static_cast<double>(problem_->distance(current, j));
        if (d < best_d || (d == best_d && j < best)) {
          best_d = d;
          best = j;
        }
      }
      return best;
    }
  }

  const P* problem_;
  std::uint32_t n_;
  std::size_t min_new_edges_ = 0;  // 0: tours are built from nothing
  SourceTour source_;
  std::size_t k_ = 0;
  double alpha_ = 1.0;
  EdgeTrail trail_;
  std::vector<double> eta_beta_;
  std::vector<double> weight_;
  std::vector<Scratch> scratch_;
  StopToken stop_;  ///< never expires unless set_stop() says otherwise
};

template <PermutationProblem P>
struct family_of<P> {
  using type = PermutationFamily<P>;
};

}  // namespace antslam::aco
