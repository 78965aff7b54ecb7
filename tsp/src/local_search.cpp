#include "antslam/tsp/local_search.hpp"

#include <stdexcept>

#include "moves.hpp"

namespace antslam::tsp {

std::string_view to_string(LocalSearchKind kind) {
  switch (kind) {
    case LocalSearchKind::none:
      return "none";
    case LocalSearchKind::two_opt:
      return "2opt";
    case LocalSearchKind::two_half_opt:
      return "2.5opt";
    case LocalSearchKind::three_opt:
      return "3opt";
  }
  return "?";
}

std::optional<LocalSearchKind> parse_local_search(std::string_view name) {
  for (LocalSearchKind k : {LocalSearchKind::none, LocalSearchKind::two_opt,
                            LocalSearchKind::two_half_opt, LocalSearchKind::three_opt})
    if (to_string(k) == name) return k;
  return std::nullopt;
}

TourLocalSearch::Workspace TourLocalSearch::make_workspace(const TspProblem& problem) const {
  Workspace w;
  w.queue.resize(problem.size());
  w.queued.assign(problem.size(), 0);
  return w;
}

void TourLocalSearch::improve(const TspProblem& problem, std::vector<std::uint32_t>& tour,
                              Workspace& w, aco::Rng& rng, const aco::StopToken& stop) const {
  if (!begin(problem, tour, w)) return;
  const auto n = static_cast<std::uint32_t>(tour.size());
  // Don't-look bits: the active cities in random order (ACOTSP's random permutation).
  const bool changed_only = settings_.queue_changed_only && w.previous.size() == n;
  if (changed_only) {  // cities with a tour edge that is not in the previous tour
    std::fill(w.queued.begin(), w.queued.end(), 0);
    w.previous_position.resize(n);
    for (std::uint32_t p = 0; p < n; ++p) w.previous_position[w.previous[p]] = p;
    for (std::uint32_t p = 0; p < n; ++p) {
      const std::uint32_t c = tour[p], s = tour[p + 1 == n ? 0 : p + 1];
      const std::uint32_t q = w.previous_position[c];
      if (w.previous[q + 1 == n ? 0 : q + 1] != s && w.previous[q == 0 ? n - 1 : q - 1] != s)
        w.queued[c] = w.queued[s] = 1;
    }
  } else {
    std::fill(w.queued.begin(), w.queued.end(), 1);
  }
  std::uint32_t count = 0;
  aco::Rng local = rng;  // the colony's generators share cache lines; draw from a copy
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = local.below(i + 1);
    w.queue[i] = w.queue[j];
    w.queue[j] = i;
  }
  for (std::uint32_t i = 0; i < n; ++i)
    if (w.queued[w.queue[i]]) w.queue[count++] = w.queue[i];
  rng = local;
  search(problem, tour, w, count, stop);
}

void TourLocalSearch::improve(const TspProblem& problem, std::vector<std::uint32_t>& tour,
                              Workspace& w, aco::Rng& rng, const aco::StopToken& stop,
                              std::span<const std::uint32_t> new_edges) const {
  if (!begin(problem, tour, w)) return;
  // Only the endpoints of the new edges are active, in random order; the queue starts empty
  // and the search leaves it empty, so nothing of size n is touched.
  std::uint32_t count = 0;
  aco::Rng local = rng;
  for (const std::uint32_t c : new_edges) {
    if (c >= tour.size()) throw std::invalid_argument("local search: new edge city out of range");
    if (w.queued[c]) continue;
    w.queued[c] = 1;
    const std::uint32_t j = local.below(count + 1);
    w.queue[count] = w.queue[j];
    w.queue[j] = c;
    ++count;
  }
  rng = local;
  search(problem, tour, w, count, stop);
}

bool TourLocalSearch::begin(const TspProblem& problem, const std::vector<std::uint32_t>& tour,
                            Workspace& w) const {
  w.stats = {};
  if (settings_.kind == LocalSearchKind::none || tour.size() < 4) return false;  // n = 3: one tour
  if (tour.size() != problem.size())
    throw std::invalid_argument("local search: tour size differs from n");
  return true;
}

void TourLocalSearch::search(const TspProblem& problem, std::vector<std::uint32_t>& tour,
                             Workspace& w, std::uint32_t count, const aco::StopToken& stop) const {
  if (tour.size() >= settings_.two_level_from) {
    w.large.assign(tour, problem);
    run_queue(problem, w.large, w, count, stop);
    w.large.copy_to(tour);
  } else {
    w.tour.assign(tour, problem);
    run_queue(problem, w.tour, w, count, stop);
    w.tour.copy_to(tour);
  }
  if (settings_.queue_changed_only) w.previous.assign(tour.begin(), tour.end());
}

template <class Tour>
void TourLocalSearch::run_queue(const TspProblem& problem, Tour& moves_on, Workspace& w,
                                std::uint32_t count, const aco::StopToken& stop) const {
  const auto n = static_cast<std::uint32_t>(problem.size());
  const std::size_t k = std::min(settings_.neighbours, problem.neighbours(0).size());
  const auto step = settings_.kind == LocalSearchKind::two_opt ? &detail::two_opt_step<Tour>
                    : settings_.kind == LocalSearchKind::two_half_opt
                        ? &detail::two_half_opt_step<Tour>
                        : &detail::three_opt_step<Tour>;
  std::uint32_t head = 0;
  detail::Touched touched;
  // The stop token is polled every 64 cities and every 16 moves: on a poor tour of a million
  // cities one city can take many moves, each reversing up to n / 2 cities of an array.
  while (count > 0 && !w.stats.stopped) {
    if ((++w.stats.examined & 63U) == 0 && stop.expired()) {
      w.stats.stopped = true;
      break;
    }
    const std::uint32_t city = w.queue[head];
    head = head + 1 == n ? 0 : head + 1;
    --count;
    w.queued[city] = 0;
    while (step(problem, moves_on, city, k, touched)) {
      if ((++w.stats.moves & 15U) == 0 && stop.expired()) {
        w.stats.stopped = true;
        break;
      }
      for (std::size_t t = 0; t < touched.count; ++t) {
        const std::uint32_t c = touched.cities[t];
        if (w.queued[c] || c == city) continue;
        w.queued[c] = 1;
        const std::uint32_t tail = head + count;
        w.queue[tail >= n ? tail - n : tail] = c;
        ++count;
      }
    }
  }
  for (std::uint32_t r = 0; r < count; ++r) {  // a stopped search leaves its queue clean
    const std::uint32_t at = head + r;
    w.queued[w.queue[at >= n ? at - n : at]] = 0;
  }
}

}  // namespace antslam::tsp
