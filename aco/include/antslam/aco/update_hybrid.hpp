#pragma once
// The AntSLAM hybrid of Ant System, ACS and MAX-MIN (paper Sec. III-B, Algorithm 2): every ant
// deposits 1/W (eq. 12), except every glob_best_freq-th iteration when only the global-best and
// the iteration-best ant do (lines 28-34); pheromone is capped at tau_max and starts at
// tau_init. Use it with the UniformExploration construction rule (lines 13-20).
//
// The paper leaves the evaporation rate open. On the synthetic presets (N = 9, 15, 24; M = 20;
// 3000 iterations x 20 ants; 100 trials on each of three sets per size) the mean final weight
// falls monotonically as rho grows from 0.01 to 1, and rho = 1 is best by a wide margin
// (docs/slamgraph.md, "Evaporation rate"): the hybrid works best when each iteration's deposits
// replace the trail instead of adding to it. That is the default; set rho for other regimes.

#include <cstdint>
#include <limits>

#include "antslam/aco/update_context.hpp"

namespace antslam::aco {

struct HybridUpdate {
  double rho = 1.0;                  ///< evaporation rate of eq. (2), in (0, 1]; see above
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
    trail.evaporate(rho, v.parallel);
    // Algorithm 2 line 29: `iteration` has already been incremented (line 28).
    if (v.iteration % glob_best_freq != 0) {
      for (const Solution& ant : v.ants)
        trail.deposit(ant.path, deposit_amount(deposit, ant.cost), v.parallel);
    } else {
      trail.deposit(v.global_best.path, deposit_amount(deposit, v.global_best.cost), v.parallel);
      trail.deposit(v.iteration_best.path, deposit_amount(deposit, v.iteration_best.cost),
                    v.parallel);
    }
    trail.clamp(0.0, tau_max, v.parallel);
  }
};

}  // namespace antslam::aco
