#pragma once
// The NLopt procedure of refine.hpp for any smooth objective with a kernel width (the alignment
// objective of a fragment set, the vertex objective of a pose graph): the plain minimisation of
// eq. (10) and the graduated stages, the best point evaluated kept, a time budget over all
// stages, and a stop request honoured at the next evaluation.
//
// Objective: dimension(), evaluate(x, gradient) -> Scores (weight at the current width),
// set_kernel_width(s).

#include <nlopt.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <vector>

#include "antslam/slamgraph/refine.hpp"

namespace antslam::slam::detail {

nlopt::algorithm nlopt_algorithm(RefineAlgorithm a);

/// The outcome of minimise_in_stages.
struct StagedMinimum {
  std::vector<double> x;   ///< the best point: of the plain run, or of the graduated one
  Scores start;            ///< objectives at the start (width 1)
  Scores scores;           ///< objectives at x (width 1)
  int evaluations = 0;     ///< objective evaluations of every stage
  bool graduated = false;  ///< the graduated stages gave x
};

template <class Objective>
class NloptStages {
 public:
  NloptStages(Objective& objective, const RefineSettings& settings)
      : objective_(&objective), settings_(settings) {}

  /// Plain NLopt from x, then (settings.graduated) the stages s_0 = sqrt(chi2 of x) >= every
  /// term's Mahalanobis distance, s_0 / f, ..., 1; the result with the lower eq. (10) weight.
  /// No stage starts once settings.time_limit_s is spent.
  StagedMinimum run(const std::vector<double>& x, const std::vector<double>& lower,
                    const std::vector<double>& upper) {
    began_ = std::chrono::steady_clock::now();
    StagedMinimum result;
    objective_->set_kernel_width(1.0);
    result.start = objective_->evaluate(x);
    result.x = minimise(x, lower, upper, result.evaluations);
    result.scores = objective_->evaluate(result.x);
    if (settings_.graduated && !spent()) {
      double width = std::max(1.0, std::sqrt(result.start.chi2));
      std::vector<double> point = x;
      for (;;) {
        if (spent()) break;
        objective_->set_kernel_width(width);
        point = minimise(point, lower, upper, result.evaluations);
        if (width == 1.0) break;
        width = std::max(1.0, width / settings_.graduation_factor);
      }
      objective_->set_kernel_width(1.0);  // the stages may have ended early, at a wider kernel
      const Scores graduated = objective_->evaluate(point);
      if (graduated.weight < result.scores.weight) {
        result.x = point;
        result.scores = graduated;
        result.graduated = true;
      }
    }
    result.evaluations += 2;
    return result;
  }

 private:
  /// What the NLopt callback sees.
  struct Tracker {
    Objective* objective;
    const std::stop_token* stop;
    std::vector<double> best_x;
    double best = std::numeric_limits<double>::infinity();
    int evaluations = 0;
  };

  static double callback(unsigned n, const double* x, double* grad, void* data) {
    auto& t = *static_cast<Tracker*>(data);
    if (t.stop->stop_requested()) throw nlopt::forced_stop();
    const Scores s =
        t.objective->evaluate({x, n}, grad ? std::span<double>(grad, n) : std::span<double>());
    ++t.evaluations;
    if (s.weight < t.best) {
      t.best = s.weight;
      t.best_x.assign(x, x + n);
    }
    return s.weight;
  }

  /// Seconds left of the time budget (0 = no limit).
  double remaining() const {
    if (settings_.time_limit_s <= 0.0) return 0.0;
    const std::chrono::duration<double> used = std::chrono::steady_clock::now() - began_;
    return std::max(1e-6, settings_.time_limit_s - used.count());
  }

  /// Whether the time budget is used up (never without one).
  bool spent() const {
    return settings_.time_limit_s > 0.0 &&
           std::chrono::duration<double>(std::chrono::steady_clock::now() - began_).count() >=
               settings_.time_limit_s;
  }

  /// NLopt from x in the box on the objective at its current width; the best point evaluated.
  std::vector<double> minimise(const std::vector<double>& x, const std::vector<double>& lower,
                               const std::vector<double>& upper, int& evaluations) {
    Tracker tracker{objective_, &settings_.stop, x};
    tracker.best = objective_->evaluate(x).weight;
    nlopt::opt opt(nlopt_algorithm(settings_.algorithm), static_cast<unsigned>(x.size()));
    opt.set_min_objective(callback, &tracker);
    opt.set_lower_bounds(lower);
    opt.set_upper_bounds(upper);
    opt.set_maxeval(settings_.max_evaluations);
    opt.set_ftol_rel(settings_.relative_tolerance);
    if (const double seconds = remaining(); seconds > 0.0) opt.set_maxtime(seconds);
    if (settings_.algorithm == RefineAlgorithm::lbfgs)
      opt.set_vector_storage(static_cast<unsigned>(settings_.lbfgs_memory));
    std::vector<double> point = x;
    double final_weight = 0.0;
    try {
      opt.optimize(point, final_weight);
    } catch (const nlopt::roundoff_limited&) {
      // Roundoff ends the search; the best point evaluated so far stands.
    } catch (const std::runtime_error&) {
      // NLOPT_FAILURE (e.g. a line search that cannot progress) or a stop request: same.
    }
    evaluations += tracker.evaluations + 1;
    return tracker.best_x;
  }

  Objective* objective_;
  RefineSettings settings_;
  std::chrono::steady_clock::time_point began_;
};

}  // namespace antslam::slam::detail
