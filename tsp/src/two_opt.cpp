// 2-opt and 2.5-opt steps (see moves.hpp for the notation).

#include "moves.hpp"

namespace antslam::tsp::detail {

namespace {

/// The 2-opt closing of remove (t1, t2), add (t2, t3): remove (t4, t3) with t4 the
/// predecessor of t3, add (t4, t1). Applies it if it gains.
template <class Tour>
bool try_two_opt(const TspProblem& problem, Tour& tour, std::uint32_t t1, std::uint32_t t2,
                 std::uint32_t t3, double g1, bool forward, Touched& touched) {
  const std::uint32_t t4 = tour.next(t3, !forward);
  if (t4 == t2) return false;  // t3 follows t2: nothing to exchange
  if (g1 + tour.next_length(t3, !forward) - problem.distance(t1, t4) <= 0.0) return false;
  two_opt_move(tour, t1, t2, t4, t3);
  touched.set({t1, t2, t3, t4});
  return true;
}

}  // namespace

template <class Tour>
bool two_opt_step(const TspProblem& problem, Tour& tour, std::uint32_t t1, std::size_t k,
                  Touched& touched) {
  for (const bool forward : {true, false}) {
    const std::uint32_t t2 = tour.next(t1, forward);
    const double d12 = tour.next_length(t1, forward);
    if (for_each_gainful_neighbour(problem, t2, k, d12, [&](std::uint32_t t3, double g1) {
          return t3 != t1 && try_two_opt(problem, tour, t1, t2, t3, g1, forward, touched);
        }))
      return true;
  }
  return false;
}

template <class Tour>
bool two_half_opt_step(const TspProblem& problem, Tour& tour, std::uint32_t t1, std::size_t k,
                       Touched& touched) {
  for (const bool forward : {true, false}) {
    const std::uint32_t t2 = tour.next(t1, forward);
    const std::uint32_t t2_next = tour.next(t2, forward);
    const double d12 = tour.next_length(t1, forward);
    // Gain of taking t2 out of the tour and joining its neighbours.
    const double removal = d12 + tour.next_length(t2, forward) - problem.distance(t1, t2_next);
    const auto improve = [&](std::uint32_t t3, double g1) {
      if (t3 == t1) return false;
      if (try_two_opt(problem, tour, t1, t2, t3, g1, forward, touched)) return true;
      // Node insertion: put t2 between t3 and one of its tour neighbours u.
      const double d23 = d12 - g1;
      for (const bool side : {true, false}) {
        const std::uint32_t u = tour.next(t3, side);
        if (u == t2) continue;
        const double insertion = d23 + problem.distance(t2, u) - tour.next_length(t3, side);
        if (removal - insertion <= 0.0) continue;
        move_city(tour, t2, t3, u);
        touched.set({t1, t2, t2_next, t3, u});
        return true;
      }
      return false;
    };
    if (for_each_gainful_neighbour(problem, t2, k, d12, improve)) return true;
  }
  return false;
}

template bool two_opt_step(const TspProblem&, ArrayTour&, std::uint32_t, std::size_t, Touched&);
template bool two_opt_step(const TspProblem&, TwoLevelTour&, std::uint32_t, std::size_t, Touched&);
template bool two_half_opt_step(const TspProblem&, ArrayTour&, std::uint32_t, std::size_t,
                                Touched&);
template bool two_half_opt_step(const TspProblem&, TwoLevelTour&, std::uint32_t, std::size_t,
                                Touched&);

}  // namespace antslam::tsp::detail
