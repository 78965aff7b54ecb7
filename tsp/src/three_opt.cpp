// Sequential 3-opt step (see moves.hpp for the notation). With t2 following t1, the exchange
// remove (t1, t2), add (t2, t3) leaves a Hamiltonian path plus a cycle, and t4 decides which:
//
//   t4 before t3  the 2-opt case: closing with (t4, t1) is a valid 2-opt move; otherwise add
//                 (t4, t5) and remove the one edge (t5, t6) that keeps a Hamiltonian path
//                 (t6 on the side of t5 facing t4), then close with (t6, t1).
//   t4 after t3   the path t2..t3 became a cycle; (t4, t5) must re-enter it (t5 between t2 and
//                 t3) and either of t5's cycle edges may go: t6 after t5 moves the segment
//                 t6..t3 in front of t2..t5 unreversed (the Or-opt move), t6 before t5
//                 reverses both segments.
//
// Every case is applied as two or three 2-opt moves, each a reversal of the shorter side.

#include "moves.hpp"

namespace antslam::tsp::detail {

// Not in an anonymous namespace: the explicitly instantiated three_opt_step below captures it.
template <class Tour>
struct ThreeOptSearch {
  const TspProblem& problem;
  Tour& tour;
  std::size_t k;
  Touched& touched;
  std::uint32_t t1 = 0, t2 = 0, t3 = 0;
  double g1 = 0.0;
  bool forward = true;

  double d(std::uint32_t a, std::uint32_t b) const { return problem.distance(a, b); }

  /// t4 = predecessor of t3.
  bool two_opt_side() {
    const std::uint32_t t4 = tour.next(t3, !forward);
    const double g1_open = g1 + tour.next_length(t3, !forward);  // (t3, t4) removed, not closed
    if (g1_open - d(t1, t4) > 0.0) {
      two_opt_move(tour, t1, t2, t4, t3);
      touched.set({t1, t2, t3, t4});
      return true;
    }
    return for_each_gainful_neighbour(problem, t4, k, g1_open, [&](std::uint32_t t5, double g2) {
      if (t5 == t3 || t5 == t1) return false;
      // t5 on the reversed part t2..t4: its neighbour towards t4 is its successor; on t3..t1 it
      // is its predecessor.
      const bool towards_t4 = tour.between(t2, t5, t4, forward) ? forward : !forward;
      const std::uint32_t t6 = tour.next(t5, towards_t4);
      if (t6 == t4) return false;
      if (g2 + tour.next_length(t5, towards_t4) - d(t1, t6) <= 0.0) return false;
      two_opt_move(tour, t1, t2, t4, t3);  // t1 t4 .. t2 t3 .. (closing edge (t1, t4) for now)
      two_opt_move(tour, t4, t1, t5, t6);  // replaces (t1, t4), (t6, t5) by (t4, t5), (t1, t6)
      touched.set({t1, t2, t3, t4, t5, t6});
      return true;
    });
  }

  /// t4 = successor of t3.
  bool cycle_side() {
    const std::uint32_t t4 = tour.next(t3, forward);
    if (t4 == t1) return false;
    const double g1_open = g1 + tour.next_length(t3, forward);
    return for_each_gainful_neighbour(problem, t4, k, g1_open, [&](std::uint32_t t5, double g2) {
      if (t5 == t3 || !tour.between(t2, t5, t3, forward)) return false;
      const std::uint32_t after = tour.next(t5, forward);
      if (g2 + tour.next_length(t5, forward) - d(t1, after) > 0.0) {  // t1 [t6..t3] [t2..t5] t4
        two_opt_move(tour, t1, t2, t3, t4);                           // t1 t3..t6 t5..t2 t4
        two_opt_move(tour, t1, t3, after, t5);                        // t1 t6..t3 t5..t2 t4
        two_opt_move(tour, t3, t5, t2, t4);                           // t1 t6..t3 t2..t5 t4
        touched.set({t1, t2, t3, t4, t5, after});
        return true;
      }
      if (t5 == t2) return false;
      const std::uint32_t before = tour.next(t5, !forward);
      if (g2 + tour.next_length(t5, !forward) - d(t1, before) > 0.0) {  // t1 [t6..t2] [t3..t5] t4
        two_opt_move(tour, t1, t2, before, t5);                         // t1 t6..t2 t5..t3 t4
        two_opt_move(tour, t2, t5, t3, t4);                             // t1 t6..t2 t3..t5 t4
        touched.set({t1, t2, t3, t4, t5, before});
        return true;
      }
      return false;
    });
  }
};

template <class Tour>
bool three_opt_step(const TspProblem& problem, Tour& tour, std::uint32_t t1, std::size_t k,
                    Touched& touched) {
  ThreeOptSearch<Tour> step{problem, tour, k, touched};
  step.t1 = t1;
  for (const bool forward : {true, false}) {
    step.forward = forward;
    step.t2 = tour.next(t1, forward);
    const double d12 = tour.next_length(t1, forward);
    const std::uint32_t t2_next = tour.next(step.t2, forward);
    if (for_each_gainful_neighbour(problem, step.t2, k, d12, [&](std::uint32_t t3, double g1) {
          if (t3 == t1 || t3 == t2_next) return false;
          step.t3 = t3;
          step.g1 = g1;
          return step.two_opt_side() || step.cycle_side();
        }))
      return true;
  }
  return false;
}

template bool three_opt_step(const TspProblem&, ArrayTour&, std::uint32_t, std::size_t, Touched&);
template bool three_opt_step(const TspProblem&, TwoLevelTour&, std::uint32_t, std::size_t,
                             Touched&);

}  // namespace antslam::tsp::detail
