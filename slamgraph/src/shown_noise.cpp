#include "antslam/slamgraph/shown_noise.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <nlopt.hpp>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "antslam/slamgraph/chi_square.hpp"

namespace antslam::slam {

namespace {

/// A short cycle: its residual and the parts of its covariance that scale with s_xy^2, s_theta^2
/// and s_xy s_theta (C(s) = s_xy^2 xy + s_theta^2 theta + s_xy s_theta cross).
struct ShortCycle {
  Eigen::Vector3d residual;
  Eigen::Matrix3d xy, theta, cross;

  /// The squared distance at scale s and the log-determinant of C(s); +infinity unless C(s) is
  /// positive definite.
  std::pair<double, double> distance_and_log_det(NoiseScale s) const {
    const Eigen::LDLT<Eigen::Matrix3d> ldlt(s.xy * s.xy * xy + s.theta * s.theta * theta +
                                            s.xy * s.theta * cross);
    if (ldlt.info() != Eigen::Success || !ldlt.isPositive() || !(ldlt.vectorD().minCoeff() > 0.0))
      return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    return {residual.dot(ldlt.solve(residual)), std::log(ldlt.vectorD().prod())};
  }
  double squared_distance(NoiseScale s) const { return distance_and_log_det(s).first; }
};

/// For each closure, its `partners` partners among `window` neighbours on each side in (lo, hi)
/// order whose cycle has the smallest heading variance at the stated noise; of those pairs the
/// `shortest` fraction (at least `min_shortest`) with the smallest; each pair once.
std::vector<std::pair<std::size_t, std::size_t>> short_pairs(const PoseGraph& graph,
                                                             const ChainSplit& split,
                                                             const CycleTest& test,
                                                             const ShownNoiseSettings& settings) {
  const std::size_t m = split.closures.size();
  std::vector<std::size_t> order(m);
  std::vector<std::pair<std::size_t, std::size_t>> span(m);
  for (std::size_t k = 0; k < m; ++k) {
    const PoseGraphEdge& e = graph.edges[split.closures[k]];
    span[k] = {std::min(e.from, e.to), std::max(e.from, e.to)};
    order[k] = k;
  }
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return span[a] != span[b] ? span[a] < span[b] : a < b;
  });
  // (heading variance, (k, l)) of every candidate pair kept, k < l.
  std::vector<std::pair<double, std::pair<std::size_t, std::size_t>>> by_length;
  std::vector<std::pair<double, std::size_t>> candidates;
  for (std::size_t i = 0; i < m; ++i) {
    candidates.clear();
    const std::size_t first = i > settings.window ? i - settings.window : 0;
    const std::size_t last = std::min(m, i + settings.window + 1);
    for (std::size_t j = first; j < last; ++j)
      if (j != i && test.closes_cycle(order[i], order[j]))  // (other sessions: no cycle)
        candidates.emplace_back(test.cycle(order[i], order[j]).covariance(2, 2), j);
    const std::size_t keep = std::min(settings.partners, candidates.size());
    std::partial_sort(candidates.begin(), candidates.begin() + static_cast<std::ptrdiff_t>(keep),
                      candidates.end());
    for (std::size_t c = 0; c < keep; ++c) {
      const std::size_t k = order[i], l = order[candidates[c].second];
      by_length.push_back({candidates[c].first, {std::min(k, l), std::max(k, l)}});
    }
  }
  // Each pair once, then the shortest of them overall: a true closure's neighbour along a
  // revisited place closes a cycle of a few steps, a false one's nearest partner is as far as
  // chance puts it.
  const auto same_pair = [](const auto& a, const auto& b) { return a.second == b.second; };
  std::sort(by_length.begin(), by_length.end(),
            [](const auto& a, const auto& b) { return a.second < b.second; });
  by_length.erase(std::unique(by_length.begin(), by_length.end(), same_pair), by_length.end());
  const std::size_t keep = std::min(
      by_length.size(), std::max(settings.min_shortest,
                                 static_cast<std::size_t>(settings.shortest *
                                                          static_cast<double>(by_length.size()))));
  std::partial_sort(by_length.begin(), by_length.begin() + static_cast<std::ptrdiff_t>(keep),
                    by_length.end());
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < keep; ++i) pairs.push_back(by_length[i].second);
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

/// P(X <= x) for X ~ chi-square(5): the chi-square(3) one less (x/2)^(3/2) e^(-x/2) / Gamma(5/2).
double chi_square5_cdf(double x) {
  if (!(x > 0.0)) return 0.0;
  const double gamma_5_2 = 0.75 * std::sqrt(std::numbers::pi);
  return chi_square3_cdf(x) - std::pow(0.5 * x, 1.5) * std::exp(-0.5 * x) / gamma_5_2;
}

/// The Gaussian maximum-likelihood scale of `cycles` (minimising the sum of squared distance
/// plus log-determinant over log s_xy and log s_theta), started from `start`.
NoiseScale maximum_likelihood(const std::vector<const ShortCycle*>& cycles, NoiseScale start) {
  const auto cost = [&](const std::vector<double>& u) {
    const NoiseScale s{std::exp(u[0]), std::exp(u[1])};
    double sum = 0.0;
    for (const ShortCycle* c : cycles) {
      const auto [d2, log_det] = c->distance_and_log_det(s);
      sum += d2 + log_det;
    }
    return sum;
  };
  nlopt::opt opt(nlopt::LN_NELDERMEAD, 2);
  opt.set_min_objective([](const std::vector<double>& u, std::vector<double>&,
                           void* data) { return (*static_cast<decltype(cost)*>(data))(u); },
                        const_cast<void*>(static_cast<const void*>(&cost)));
  opt.set_xtol_abs(1e-5);
  opt.set_maxeval(2000);
  opt.set_initial_step(0.3);
  std::vector<double> u{std::log(start.xy), std::log(start.theta)};
  double value = 0.0;
  try {
    opt.optimize(u, value);
  } catch (const std::exception&) {
    return start;  // NLopt's roundoff-limited stop: keep the start
  }
  return {std::exp(u[0]), std::exp(u[1])};
}

}  // namespace

ShownNoise estimate_shown_noise(const PoseGraph& graph, const ChainSplit& split,
                                const ShownNoiseSettings& settings) {
  if (!(settings.confidence > 0.0 && settings.confidence < 1.0))
    throw std::invalid_argument("shown noise: confidence must be in (0, 1), got " +
                                std::to_string(settings.confidence));
  if (!(settings.start_quantile > 0.0 && settings.start_quantile < 1.0))
    throw std::invalid_argument("shown noise: start quantile must be in (0, 1), got " +
                                std::to_string(settings.start_quantile));
  if (settings.partners == 0 || settings.window == 0)
    throw std::invalid_argument("shown noise: partners and window must be at least 1");
  if (!(settings.shortest > 0.0 && settings.shortest <= 1.0))
    throw std::invalid_argument("shown noise: the shortest fraction must be in (0, 1], got " +
                                std::to_string(settings.shortest));
  ShownNoise result;
  if (split.closures.size() < 2) return result;
  const CycleTest stated(graph, split);
  const auto pairs = short_pairs(graph, split, stated, settings);
  result.cycles = pairs.size();
  // C(1,1) = xy + theta + cross, C(2,1) = 4 xy + theta + 2 cross, C(1,2) = xy + 4 theta + 2 cross.
  const CycleTest wide_xy(at_noise_scale(graph, {2.0, 1.0}), split);
  const CycleTest wide_theta(at_noise_scale(graph, {1.0, 2.0}), split);
  std::vector<ShortCycle> cycles;
  cycles.reserve(pairs.size());
  for (const auto& [k, l] : pairs) {
    const Cycle p = stated.cycle(k, l);
    const Eigen::Matrix3d q = wide_xy.cycle(k, l).covariance;
    const Eigen::Matrix3d r = wide_theta.cycle(k, l).covariance;
    const Eigen::Matrix3d cross = 5.0 * p.covariance - q - r;
    cycles.push_back(
        {p.residual, (q - p.covariance - cross) / 3.0, (r - p.covariance - cross) / 3.0, cross});
  }
  std::vector<double> d2;
  for (const ShortCycle& c : cycles) d2.push_back(c.squared_distance({}));
  if (d2.size() < settings.min_cycles) return result;
  const auto at = d2.begin() + static_cast<std::ptrdiff_t>(settings.start_quantile *
                                                           static_cast<double>(d2.size() - 1));
  std::nth_element(d2.begin(), at, d2.end());
  // chi-square(3) quantile of the start probability: the start scale makes that quantile match.
  const double start = std::sqrt(*at / chi_square3_quantile(settings.start_quantile));
  if (!(start > 0.0) || !std::isfinite(start)) return result;
  const double threshold = chi_square3_quantile(settings.confidence);
  // A Gaussian truncated at the threshold has E[d2] = 3 F5(t) / F3(t): the trimmed maximum
  // likelihood shrinks the variance by that factor.
  const double shrink = std::sqrt(chi_square5_cdf(threshold) / chi_square3_cdf(threshold));
  NoiseScale scale{start, start};
  std::vector<const ShortCycle*> kept;
  for (result.rounds = 1; result.rounds <= settings.max_rounds; ++result.rounds) {
    kept.clear();
    for (const ShortCycle& c : cycles)
      if (c.squared_distance(scale) <= threshold) kept.push_back(&c);
    if (kept.size() < settings.min_cycles) return result;
    NoiseScale next = maximum_likelihood(kept, scale);
    next.xy /= shrink;
    next.theta /= shrink;
    const bool settled = std::abs(std::log(next.xy / scale.xy)) < 1e-3 &&
                         std::abs(std::log(next.theta / scale.theta)) < 1e-3;
    scale = next;
    if (settled) break;
  }
  result.rounds = std::min(result.rounds, settings.max_rounds);
  result.scale = scale;
  result.estimated = true;
  result.inliers = static_cast<std::size_t>(
      std::count_if(cycles.begin(), cycles.end(),
                    [&](const ShortCycle& c) { return c.squared_distance(scale) <= threshold; }));
  return result;
}

PoseGraph at_noise_scale(const PoseGraph& graph, NoiseScale scale) {
  if (!(scale.xy > 0.0 && scale.theta > 0.0 && std::isfinite(scale.xy) &&
        std::isfinite(scale.theta)))
    throw std::invalid_argument("noise scale: must be positive and finite, got " +
                                std::to_string(scale.xy) + " and " + std::to_string(scale.theta));
  const Eigen::Vector3d inverse(1.0 / scale.xy, 1.0 / scale.xy, 1.0 / scale.theta);
  PoseGraph result = graph;
  for (PoseGraphEdge& e : result.edges)
    e.information = inverse.asDiagonal() * e.information * inverse.asDiagonal();
  return result;
}

}  // namespace antslam::slam
