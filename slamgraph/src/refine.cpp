#include "slamgraph/refine.hpp"

#include <nlopt.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace antslam::slam {

namespace {

constexpr RefineAlgorithm kAlgorithms[] = {RefineAlgorithm::lbfgs, RefineAlgorithm::slsqp,
                                           RefineAlgorithm::bobyqa};

nlopt::algorithm nlopt_algorithm(RefineAlgorithm a) {
  switch (a) {
    case RefineAlgorithm::lbfgs:
      return nlopt::LD_LBFGS;
    case RefineAlgorithm::slsqp:
      return nlopt::LD_SLSQP;
    case RefineAlgorithm::bobyqa:
      return nlopt::LN_BOBYQA;
  }
  throw std::invalid_argument("unknown refinement algorithm");
}

/// What the NLopt callback sees: the objective and the best point so far.
struct Tracker {
  AlignmentObjective* objective;
  std::vector<double> best_x;
  double best = std::numeric_limits<double>::infinity();
  int evaluations = 0;
};

double callback(unsigned n, const double* x, double* grad, void* data) {
  auto& t = *static_cast<Tracker*>(data);
  const Scores s =
      t.objective->evaluate({x, n}, grad ? std::span<double>(grad, n) : std::span<double>());
  ++t.evaluations;
  if (s.weight < t.best) {
    t.best = s.weight;
    t.best_x.assign(x, x + n);
  }
  return s.weight;
}

}  // namespace

std::string_view to_string(RefineAlgorithm a) {
  switch (a) {
    case RefineAlgorithm::lbfgs:
      return "lbfgs";
    case RefineAlgorithm::slsqp:
      return "slsqp";
    case RefineAlgorithm::bobyqa:
      return "bobyqa";
  }
  return "?";
}

RefineAlgorithm parse_refine_algorithm(std::string_view name) {
  for (RefineAlgorithm a : kAlgorithms)
    if (to_string(a) == name) return a;
  throw std::invalid_argument("unknown NLopt algorithm '" + std::string(name) +
                              "' (expected lbfgs, slsqp or bobyqa)");
}

void validate(const RefineSettings& settings) {
  if (!(settings.bound_sigmas >= 0.0) || !std::isfinite(settings.bound_sigmas))
    throw std::invalid_argument("refine: bound_sigmas must be finite and >= 0");
  if (settings.max_evaluations <= 0 || settings.lbfgs_memory <= 0)
    throw std::invalid_argument("refine: max_evaluations and lbfgs_memory must be positive");
  if (!(settings.relative_tolerance >= 0.0) || !(settings.time_limit_s >= 0.0))
    throw std::invalid_argument("refine: tolerance and time limit must be >= 0");
  if (!(settings.graduation_factor > 1.0) || !std::isfinite(settings.graduation_factor))
    throw std::invalid_argument("refine: graduation_factor must be a finite number > 1");
}

Refiner::Refiner(const FragmentSet& set, const RefineSettings& settings)
    : objective_(set), settings_(settings) {
  validate(settings);
  for (std::size_t i = 1; i < set.fragments.size(); ++i) {
    const Gaussian2& g = *set.fragments[i].alignment;
    Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
    for (const Pose2& s : set.fragments[i].samples) {
      const Eigen::Vector3d r = g.residual(s);  // offset from the mean, angle wrapped
      lo = lo.cwiseMin(r);
      hi = hi.cwiseMax(r);
    }
    const Eigen::Vector3d widen = settings.bound_sigmas * g.covariance().diagonal().cwiseSqrt();
    const Eigen::Vector3d mu = g.mean().vector();
    for (int d = 0; d < 3; ++d) {
      lower_.push_back(mu[d] + lo[d] - widen[d]);
      upper_.push_back(mu[d] + hi[d] + widen[d]);
    }
    mean_angle_.push_back(g.mean().theta);
  }
}

std::vector<double> Refiner::minimise(const std::vector<double>& x,
                                      const std::vector<double>& lower,
                                      const std::vector<double>& upper, double seconds,
                                      int& evaluations) {
  Tracker tracker{&objective_, x};
  tracker.best = objective_.evaluate(x).weight;
  nlopt::opt opt(nlopt_algorithm(settings_.algorithm), static_cast<unsigned>(x.size()));
  opt.set_min_objective(callback, &tracker);
  opt.set_lower_bounds(lower);
  opt.set_upper_bounds(upper);
  opt.set_maxeval(settings_.max_evaluations);
  opt.set_ftol_rel(settings_.relative_tolerance);
  if (seconds > 0.0) opt.set_maxtime(seconds);
  if (settings_.algorithm == RefineAlgorithm::lbfgs)
    opt.set_vector_storage(static_cast<unsigned>(settings_.lbfgs_memory));
  std::vector<double> point = x;
  double final_weight = 0.0;
  try {
    opt.optimize(point, final_weight);
  } catch (const nlopt::roundoff_limited&) {
    // Roundoff ends the search; the best point evaluated so far stands.
  } catch (const std::runtime_error&) {
    // NLOPT_FAILURE (e.g. a line search that cannot progress): same.
  }
  evaluations += tracker.evaluations + 1;
  return tracker.best_x;
}

RefineResult Refiner::refine(std::span<const Pose2> start) {
  return refine(start, settings_.time_limit_s);
}

RefineResult Refiner::refine(std::span<const Pose2> start, double seconds) {
  if (!(seconds >= 0.0)) throw std::invalid_argument("refine: time limit must be >= 0");
  std::vector<double> x = AlignmentObjective::pack(start);
  if (x.size() != objective_.dimension())
    throw std::invalid_argument("refine: got " + std::to_string(start.size()) +
                                " alignments, expected " +
                                std::to_string(objective_.dimension() / 3));
  std::vector<double> lower = lower_, upper = upper_;
  for (std::size_t i = 0; i < mean_angle_.size(); ++i) {
    double& theta = x[3 * i + 2];
    theta = mean_angle_[i] + wrap_angle(theta - mean_angle_[i]);
    for (std::size_t d = 3 * i; d < 3 * i + 3; ++d) {
      lower[d] = std::min(lower[d], x[d]);
      upper[d] = std::max(upper[d], x[d]);
    }
  }
  const auto began = std::chrono::steady_clock::now();
  // Seconds left for NLopt (0 = no limit), and whether the budget is spent.
  const auto remaining = [&] {
    if (seconds <= 0.0) return 0.0;
    const std::chrono::duration<double> used = std::chrono::steady_clock::now() - began;
    return std::max(1e-6, seconds - used.count());
  };
  const auto spent = [&] {
    return seconds > 0.0 &&
           std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count() >=
               seconds;
  };
  RefineResult result;
  objective_.set_kernel_width(1.0);
  result.start = objective_.evaluate(x);
  std::vector<double> best = minimise(x, lower, upper, remaining(), result.evaluations);
  result.scores = objective_.evaluate(best);
  if (settings_.graduated && !spent()) {
    // Stages s_0 = sqrt(chi2) >= every term's Mahalanobis distance, s_0 / f, ..., 1.
    double width = std::max(1.0, std::sqrt(result.start.chi2));
    std::vector<double> point = x;
    for (;;) {
      if (spent()) break;
      objective_.set_kernel_width(width);
      point = minimise(point, lower, upper, remaining(), result.evaluations);
      if (width == 1.0) break;
      width = std::max(1.0, width / settings_.graduation_factor);
    }
    objective_.set_kernel_width(1.0);  // the stages may have ended early, at a wider kernel
    const Scores graduated = objective_.evaluate(point);
    if (graduated.weight < result.scores.weight) {
      best = point;
      result.scores = graduated;
      result.graduated = true;
    }
  }
  result.alignments = AlignmentObjective::unpack(best);
  result.evaluations += 2;
  return result;
}

}  // namespace antslam::slam
