#pragma once
// One improvement step of each neighbourhood from city t1, in the sequential-exchange notation
// of Lin & Kernighan (1973): remove (t1, t2), add (t2, t3), remove (t3, t4), add (t4, t5),
// remove (t5, t6), close with (t6, t1). t2 is t1's successor in orientation `forward` (both
// orientations are tried); g_i is the partial gain after adding edge i. A step applies the
// first exchange with positive total gain, records the cities whose edges changed in `touched`
// and returns true; it returns false when t1 has no improving move.

#include <array>
#include <cassert>
#include <cstddef>
#include <cstdint>

#include "antslam/tsp/array_tour.hpp"
#include "antslam/tsp/problem.hpp"
#include "antslam/tsp/two_level_tour.hpp"

namespace antslam::tsp::detail {

struct Touched {
  std::array<std::uint32_t, 6> cities{};
  std::size_t count = 0;
  void set(std::initializer_list<std::uint32_t> list) {
    count = 0;
    for (std::uint32_t c : list) cities[count++] = c;
  }
};

/// The gain criterion over a neighbour list: calls f(j, gain - d(i, j)) for the neighbours j of
/// i, nearest first, while that partial gain is positive (the lists are sorted, so no later
/// neighbour gains either). Returns true as soon as f does (f applied a move).
template <class F>
bool for_each_gainful_neighbour(const TspProblem& problem, std::uint32_t i, std::size_t k,
                                double gain, F&& f) {
  const auto near = problem.neighbours(i);
  const auto near_d = problem.neighbour_distances(i);
  for (std::size_t r = 0; r < k; ++r) {
    const double partial = gain - near_d[r];
    if (partial <= 0.0) return false;
    if (f(near[r], partial)) return true;
  }
  return false;
}

/// Removes edges (p1, p2) and (q1, q2) and adds (p1, q1) and (p2, q2). Requires p2 and q2 to
/// follow p1 and q1 in the same orientation (both succ or both pred).
template <class Tour>
void two_opt_move(Tour& tour, std::uint32_t p1, std::uint32_t p2, std::uint32_t q1,
                  std::uint32_t q2) {
  const bool forward = p2 == tour.succ(p1);
  assert(p2 == tour.next(p1, forward) && q2 == tour.next(q1, forward));
  static_cast<void>(q2);
  if (forward) {
    tour.reverse_path(p2, q1);
  } else {
    tour.reverse_path(q1, p2);
  }
}

/// Moves city x between the adjacent cities a and b (neither is x): two 2-opt moves.
template <class Tour>
void move_city(Tour& tour, std::uint32_t x, std::uint32_t a, std::uint32_t b) {
  const bool forward = b == tour.succ(a);  // orientation in which b follows a
  const std::uint32_t p = tour.next(x, !forward);
  const std::uint32_t q = tour.next(x, forward);
  two_opt_move(tour, p, x, a, b);  // p a ... q x b
  two_opt_move(tour, p, a, q, x);  // p q ... a x b
}

// The steps, for either tour representation (ArrayTour, TwoLevelTour).
template <class Tour>
bool two_opt_step(const TspProblem& problem, Tour& tour, std::uint32_t t1, std::size_t k,
                  Touched& touched);
template <class Tour>
bool two_half_opt_step(const TspProblem& problem, Tour& tour, std::uint32_t t1, std::size_t k,
                       Touched& touched);
template <class Tour>
bool three_opt_step(const TspProblem& problem, Tour& tour, std::uint32_t t1, std::size_t k,
                    Touched& touched);

}  // namespace antslam::tsp::detail
