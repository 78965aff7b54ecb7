#pragma once
// One improvement step of each neighbourhood from city t1, in the sequential-exchange notation
// of Lin & Kernighan (1973): remove (t1, t2), add (t2, t3), remove (t3, t4), add (t4, t5),
// remove (t5, t6), close with (t6, t1). t2 is t1's successor in orientation `forward` (both
// orientations are tried); g_i is the partial gain after adding edge i. A step applies the
// first exchange with positive total gain, records the cities whose edges changed in `touched`
// and returns true; it returns false when t1 has no improving move.

#include <array>
#include <cstddef>
#include <cstdint>

#include "tsp/array_tour.hpp"
#include "tsp/problem.hpp"

namespace antslam::tsp::detail {

struct Touched {
  std::array<std::uint32_t, 6> cities{};
  std::size_t count = 0;
  void set(std::initializer_list<std::uint32_t> list) {
    count = 0;
    for (std::uint32_t c : list) cities[count++] = c;
  }
};

bool two_opt_step(const TspProblem& problem, ArrayTour& tour, std::uint32_t t1, std::size_t k,
                  Touched& touched);
bool two_half_opt_step(const TspProblem& problem, ArrayTour& tour, std::uint32_t t1, std::size_t k,
                       Touched& touched);
bool three_opt_step(const TspProblem& problem, ArrayTour& tour, std::uint32_t t1, std::size_t k,
                    Touched& touched);

}  // namespace antslam::tsp::detail
