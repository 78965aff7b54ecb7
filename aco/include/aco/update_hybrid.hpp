#pragma once
// The AntSLAM hybrid of Ant System, ACS and MAX-MIN (paper Sec. III-B, Algorithm 2): every ant
// deposits 1/W (eq. 12), except every glob_best_freq-th iteration when only the global-best and
// the iteration-best ant do (lines 28-34); pheromone is capped at tau_max and starts at
// tau_init. Use it with the UniformExploration construction rule (lines 13-20).

#include <cstdint>
#include <limits>

#include "aco/update_context.hpp"

namespace antslam::aco {

struct HybridUpdate {
  double rho = 0.05;                 ///< evaporation rate of eq. (2); the paper leaves it open
  std::uint64_t glob_best_freq = 5;  ///< every this-th iteration only the two best ants deposit
  double tau_max = 10000.0;          ///< upper pheromone bound (paper Sec. IV)
  double tau_init = 100.0;           ///< initial pheromone (paper Sec. IV)
  double deposit = 1.0;              ///< numerator Q of the deposit Q/W; eq. (12) has Q = 1

  template <class Trail>
  void initialize(Trail& trail, const InitContext&) const {
    trail.fill(tau_init);
  }

  template <class Trail>
  void apply(Trail& trail, const IterationView& v) const {
    trail.evaporate(rho);
    // Algorithm 2 line 29: `iteration` has already been incremented (line 28).
    if (v.iteration % glob_best_freq != 0) {
      for (const Solution& ant : v.ants) trail.deposit(ant.path, deposit_amount(deposit, ant.cost));
    } else {
      trail.deposit(v.global_best.path, deposit_amount(deposit, v.global_best.cost));
      trail.deposit(v.iteration_best.path, deposit_amount(deposit, v.iteration_best.cost));
    }
    trail.clamp(0.0, tau_max);
  }
};

}  // namespace antslam::aco
