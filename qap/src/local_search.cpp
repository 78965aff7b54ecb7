#include "antslam/qap/local_search.hpp"

#include <utility>

namespace antslam::qap {

std::int64_t swap_delta(const Instance& instance, std::span<const std::uint32_t> p, std::uint32_t r,
                        std::uint32_t s) {
  const auto a = [&](std::size_t i, std::size_t j) { return instance.flow(i, j); };
  const auto b = [&](std::size_t i, std::size_t j) { return instance.distance(p[i], p[j]); };
  // Taillard (1991): the pairs inside {r, s}, then those with one end k outside it.
  std::int64_t delta =
      (a(r, r) - a(s, s)) * (b(s, s) - b(r, r)) + (a(r, s) - a(s, r)) * (b(s, r) - b(r, s));
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (k == r || k == s) continue;
    delta += (a(k, r) - a(k, s)) * (b(k, s) - b(k, r)) + (a(r, k) - a(s, k)) * (b(s, k) - b(r, k));
  }
  return delta;
}

void PairSwapLocalSearch::improve(const QapProblem& problem, std::vector<std::uint32_t>& assignment,
                                  Workspace&, aco::Rng&, const aco::StopToken& stop) const {
  const Instance& instance = problem.instance();
  const auto n = static_cast<std::uint32_t>(assignment.size());
  while (!stop.expired()) {
    std::int64_t best = 0;
    std::uint32_t best_r = 0;
    std::uint32_t best_s = 0;
    for (std::uint32_t r = 0; r < n; ++r)
      for (std::uint32_t s = r + 1; s < n; ++s) {
        const std::int64_t delta = swap_delta(instance, assignment, r, s);
        if (delta < best) {
          best = delta;
          best_r = r;
          best_s = s;
        }
      }
    if (best == 0) return;
    std::swap(assignment[best_r], assignment[best_s]);
  }
}

}  // namespace antslam::qap
