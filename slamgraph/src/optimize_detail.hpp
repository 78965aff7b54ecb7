#pragma once
// Shared by the optimize*.cpp files: the clock and convergence record of one run, and the
// method runners.

#include <algorithm>
#include <chrono>

#include "antslam/slamgraph/optimize.hpp"

namespace antslam::slam::detail {

/// Keeps time and records every improvement of the best weight.
class Recorder {
 public:
  Recorder(OptimizeResult& result, const OptimizeObserver& observer)
      : result_(&result), observer_(&observer), start_(std::chrono::steady_clock::now()) {}

  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

  /// Records a point if `weight` improves on the best so far; returns whether it did.
  bool improve(std::uint64_t iteration, std::uint64_t evaluations, double weight) {
    if (!result_->convergence.empty() && weight >= result_->convergence.back().best_weight)
      return false;
    const ConvergencePoint point{iteration, evaluations, elapsed(), weight};
    result_->convergence.push_back(point);
    result_->time_to_best_s = point.elapsed_s;
    if (*observer_) (*observer_)(point);
    return true;
  }

 private:
  OptimizeResult* result_;
  const OptimizeObserver* observer_;
  std::chrono::steady_clock::time_point start_;
};

/// The seconds a stage may take: what is left of the run's budget `limit_s` after `used_s`, or
/// the stage's own limit `own_s` if smaller (0 = no limit, for both and for the result; a spent
/// budget leaves a microsecond, so that the stage stops at once rather than never).
inline double stage_budget(double limit_s, double used_s, double own_s) {
  if (limit_s <= 0.0) return own_s;
  const double left = std::max(1e-6, limit_s - used_s);
  return own_s > 0.0 ? std::min(own_s, left) : left;
}

/// The ACO methods (with hybrid+nlopt's refinement). Fills choice, alignments, iterations,
/// evaluations and the convergence record.
void run_aco(const FragmentSet& set, const OptimizeSettings& settings, Recorder& recorder,
             OptimizeResult& result);

}  // namespace antslam::slam::detail
