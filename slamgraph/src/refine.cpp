#include "antslam/slamgraph/refine.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "nlopt_stages.hpp"

namespace antslam::slam {

namespace {

constexpr RefineAlgorithm kAlgorithms[] = {RefineAlgorithm::lbfgs, RefineAlgorithm::slsqp,
                                           RefineAlgorithm::bobyqa};

}  // namespace

namespace detail {

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

}  // namespace detail

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
  RefineSettings budgeted = settings_;
  budgeted.time_limit_s = seconds;
  const detail::StagedMinimum m =
      detail::NloptStages<AlignmentObjective>(objective_, budgeted).run(x, lower, upper);
  RefineResult result;
  result.alignments = AlignmentObjective::unpack(m.x);
  result.start = m.start;
  result.scores = m.scores;
  result.evaluations = m.evaluations;
  result.graduated = m.graduated;
  return result;
}

}  // namespace antslam::slam
