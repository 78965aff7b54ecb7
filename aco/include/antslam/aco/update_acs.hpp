#pragma once
// Ant Colony System (Dorigo & Gambardella 1997): only the best-so-far ant updates globally, and
// ants erode the pheromone of the edges they use as they move (local update). Use it with the
// PseudoRandomProportional construction rule.

#include "antslam/aco/update_context.hpp"

namespace antslam::aco {

struct AcsUpdate {
  double rho = 0.1;  ///< global evaporation rate
  double xi = 0.1;   ///< local evaporation rate

  double tau0 = 0.0;  ///< initial and local-update target; set by initialize() to 1 / (n C_nn)

  template <class Trail>
  void initialize(Trail& trail, const InitContext& c) {
    tau0 = 1.0 / (static_cast<double>(c.decisions) * c.reference_cost);
    trail.fill(tau0);
  }

  /// Local update tau <- (1 - xi) tau + xi tau0, applied to each component an ant uses.
  void local_update(double& tau) const { tau = (1.0 - xi) * tau + xi * tau0; }

  /// Global update on the best-so-far path only: tau <- (1 - rho) tau + rho / L_best.
  template <class Trail>
  void apply(Trail& trail, const IterationView& v) const {
    const double amount = deposit_amount(rho, v.global_best.cost);
    const double keep = 1.0 - rho;
    const auto global_update = [&](double& t) { t = keep * t + amount; };
    trail.update_path(v.global_best.path, global_update, v.parallel);
  }
};

}  // namespace antslam::aco
