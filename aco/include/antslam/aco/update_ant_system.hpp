#pragma once
// Ant System and its two elitist refinements (Dorigo & Stuetzle 2004, Sec. 3.3; defaults from
// their Table 3.3 for the TSP without local search).

#include <algorithm>
#include <cstddef>

#include "antslam/aco/update_context.hpp"

namespace antslam::aco {

/// Ant System: every ant deposits 1/L on its path, eqs. (2)-(3).
struct AntSystemUpdate {
  double rho = 0.5;  ///< evaporation rate of eq. (2), in (0, 1]

  template <class Trail>
  void initialize(Trail& trail, const InitContext& c) const {
    trail.fill(static_cast<double>(c.ants) / c.reference_cost);  // tau0 = m / C_nn
  }
  template <class Trail>
  void apply(Trail& trail, const IterationView& v) const {
    trail.evaporate(rho, v.parallel);
    for (const Solution& ant : v.ants)
      trail.deposit(ant.path, deposit_amount(1.0, ant.cost), v.parallel);
  }
};

/// Elitist Ant System: Ant System plus an extra deposit of e/L_best on the best-so-far path.
struct ElitistUpdate {
  double rho = 0.5;           ///< evaporation rate of eq. (2)
  double elite_weight = 0.0;  ///< e; 0 = the number of decisions n (the book's default)

  template <class Trail>
  void initialize(Trail& trail, const InitContext& c) {
    if (elite_weight <= 0.0) elite_weight = static_cast<double>(c.decisions);
    trail.fill((elite_weight + static_cast<double>(c.ants)) / (rho * c.reference_cost));
  }
  template <class Trail>
  void apply(Trail& trail, const IterationView& v) const {
    trail.evaporate(rho, v.parallel);
    for (const Solution& ant : v.ants)
      trail.deposit(ant.path, deposit_amount(1.0, ant.cost), v.parallel);
    trail.deposit(v.global_best.path, deposit_amount(elite_weight, v.global_best.cost), v.parallel);
  }
};

/// Rank-based Ant System: the w-1 best ants of the iteration deposit (w - r)/L_r, the best-so-far
/// path w/L_best.
struct RankUpdate {
  double rho = 0.1;       ///< evaporation rate of eq. (2)
  std::size_t width = 6;  ///< w: ants ranked 1..w-1 deposit, plus the best-so-far

  template <class Trail>
  void initialize(Trail& trail, const InitContext& c) const {
    const auto w = static_cast<double>(width);
    trail.fill(0.5 * w * (w - 1.0) / (rho * c.reference_cost));
  }
  template <class Trail>
  void apply(Trail& trail, const IterationView& v) const {
    trail.evaporate(rho, v.parallel);
    const std::size_t ranked = std::min(width - 1, v.ranking.size());
    for (std::size_t r = 0; r < ranked; ++r) {
      const Solution& ant = v.ants[v.ranking[r]];
      trail.deposit(ant.path, deposit_amount(static_cast<double>(width - 1 - r), ant.cost),
                    v.parallel);
    }
    trail.deposit(v.global_best.path,
                  deposit_amount(static_cast<double>(width), v.global_best.cost), v.parallel);
  }
};

}  // namespace antslam::aco
