#pragma once
// MAX-MIN Ant System (Stuetzle & Hoos 2000), with the iteration-best / best-so-far schedule and
// trail re-initialisation of Stuetzle's ACOTSP.

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "antslam/aco/update_context.hpp"

namespace antslam::aco {

struct MaxMinSettings {
  double rho = 0.02;                  ///< evaporation rate (0.02 without, 0.2 with local search)
  double p_best = 0.05;               ///< probability of rebuilding the best path at convergence
  bool reinitialize = true;           ///< re-initialise trails on stagnation
  double lambda = 0.05;               ///< lambda of the branching factor used to detect stagnation
  std::uint64_t check_every = 100;    ///< iterations between stagnation checks
  std::uint64_t restart_after = 250;  ///< no restart unless the restart-best is this old
  /// k > 0: re-initialise as soon as the restart-best is k iterations old, whatever the
  /// branching factor (for short runs, which end before the trails converge); 0: ACOTSP's test.
  std::uint64_t restart_stagnant = 0;
};

class MaxMinUpdate {
 public:
  explicit MaxMinUpdate(const MaxMinSettings& settings = {}) : s_(settings) {}

  template <class Trail>
  void initialize(Trail& trail, const InitContext& c) {
    decisions_ = static_cast<double>(c.decisions);
    mean_options_ = c.mean_options;
    local_search_ = c.local_search;
    focused_ = c.focused;
    max_options_ = c.max_options;
    bounds_from_best_ = false;
    bounds_cost_ = c.reference_cost;
    set_bounds(c.reference_cost);
    trail.fill(tau_max_);
    restart_best_ = Solution{};
    restart_iteration_ = restart_found_best_ = last_iteration_ = 0;
    restarts_ = 0;
    u_gb_ = 25;
  }

  template <class Trail>
  void apply(Trail& trail, const IterationView& v) {
    last_iteration_ = v.iteration;
    if (v.iteration_best.cost < restart_best_.cost) {
      restart_best_ = v.iteration_best;
      restart_found_best_ = v.iteration;
    }
    if (!bounds_from_best_ || v.global_best.cost < bounds_cost_) {  // ACOTSP: from best-so-far
      bounds_from_best_ = true;
      bounds_cost_ = v.global_best.cost;
      set_bounds(bounds_cost_);
    }

    trail.evaporate(s_.rho, v.parallel);
    const Solution* depositor = &v.iteration_best;
    if (v.iteration % u_gb_ == 0)
      depositor =
          (u_gb_ == 1 && v.iteration - restart_found_best_ > 50) ? &v.global_best : &restart_best_;
    trail.deposit(depositor->path, deposit_amount(1.0, depositor->cost), v.parallel);
    trail.clamp(tau_min_, tau_max_, v.parallel);

    update_schedule(v.iteration);
    if (s_.reinitialize && stagnated(trail, v.iteration)) {
      trail.fill(tau_max_);
      restart_best_ = Solution{};
      restart_iteration_ = v.iteration;
      ++restarts_;
    }
  }

  /// An immigrant (Colony::receive) better than the restart-best becomes the restart-best,
  /// found at the iteration boundary where it arrived: the scheduled best deposits (every u_gb
  /// iterations) lay it, and the restart test counts its age from its arrival.
  void adopt(const Solution& immigrant) {
    if (!(immigrant.cost < restart_best_.cost)) return;
    restart_best_ = immigrant;
    restart_found_best_ = last_iteration_;
  }

  const MaxMinSettings& settings() const { return s_; }
  double tau_min() const { return tau_min_; }
  double tau_max() const { return tau_max_; }
  std::uint64_t restarts() const { return restarts_; }

 private:
  /// tau_max = 1 / (rho L_best); tau_min from p_best (Stuetzle & Hoos 2000, eq. 11), or
  /// tau_max / 2n with local search (ACOTSP). Focused ants decide only where they leave the
  /// source, among the candidates: eq. 11 over one candidate list (n and avg both the list
  /// length, as FocusedACO with local search), which keeps leaving the source likely enough
  /// that an ant reaches its new edges in a few steps.
  void set_bounds(double best_cost) {
    tau_max_ = 1.0 / (s_.rho * std::max(best_cost, 1e-12));
    if (focused_) {
      const double k = std::max(max_options_, 2.0);
      const double p_dec = std::pow(s_.p_best, 1.0 / k);
      tau_min_ = tau_max_ * (1.0 - p_dec) / ((k - 1.0) * p_dec);
    } else if (local_search_) {
      tau_min_ = tau_max_ / (2.0 * decisions_);
    } else {
      const double p_dec = std::pow(s_.p_best, 1.0 / decisions_);
      tau_min_ = tau_max_ * (1.0 - p_dec) / (std::max(mean_options_ - 1.0, 1.0) * p_dec);
    }
    tau_min_ = std::min(tau_min_, tau_max_);
  }

  /// Stuetzle's restart test: every check_every iterations, a restart-best older than
  /// restart_after and a converged trail (lambda-branching factor at its minimum); or, with
  /// restart_stagnant = k, a restart-best k iterations old.
  template <class Trail>
  bool stagnated(const Trail& trail, std::uint64_t iteration) const {
    const std::uint64_t age = iteration - restart_found_best_;
    if (s_.restart_stagnant > 0) return age >= s_.restart_stagnant;
    return iteration % s_.check_every == 0 && age > s_.restart_after &&
           trail.branching_factor(s_.lambda) / trail.converged_branching() < 1.00001;
  }

  /// How often the restart-best rather than the iteration-best deposits (ACOTSP; with local
  /// search the schedule of Stuetzle's thesis).
  void update_schedule(std::uint64_t iteration) {
    if (!local_search_) {
      u_gb_ = 25;
      return;
    }
    const std::uint64_t since = iteration - restart_iteration_;
    u_gb_ = since < 25 ? 25 : since < 75 ? 5 : since < 125 ? 3 : since < 250 ? 2 : 1;
  }

  MaxMinSettings s_;
  double decisions_ = 1.0;
  double mean_options_ = 2.0;
  bool local_search_ = false;
  bool focused_ = false;
  double max_options_ = 2.0;
  bool bounds_from_best_ = false;
  double bounds_cost_ = 0.0;
  double tau_max_ = 0.0;
  double tau_min_ = 0.0;
  Solution restart_best_;
  std::uint64_t restart_iteration_ = 0;
  std::uint64_t restart_found_best_ = 0;
  std::uint64_t restarts_ = 0;
  std::uint64_t last_iteration_ = 0;  ///< the last iteration applied
  std::uint64_t u_gb_ = 25;
};

}  // namespace antslam::aco
