#pragma once
// Construction rules: how an ant picks among the feasible options, given their weights
// w_j = tau_j^alpha * eta_j^beta. Each rule offers the same two operations:
//   choose(w, rng)        draw one index (used step by step, e.g. for TSP tours);
//   distribution(w, p)    the exact probabilities choose() draws from (used to precompute
//                         per-layer sampling tables once per iteration for layered problems).

#include <cmath>
#include <cstddef>
#include <span>

#include "antslam/aco/random.hpp"

namespace antslam::aco {

namespace detail {

inline double sum(std::span<const double> w) {
  double total = 0.0;
  for (double x : w) total += x;
  return total;
}

/// Index j with probability w_j / total, from u uniform in [0, 1). If every weight is zero,
/// falls back to a uniform choice.
inline std::size_t roulette(std::span<const double> w, double total, double u) {
  if (!(total > 0.0)) return static_cast<std::size_t>(u * static_cast<double>(w.size()));
  const double target = u * total;
  double acc = 0.0;
  std::size_t last_positive = 0;
  for (std::size_t j = 0; j < w.size(); ++j) {
    if (w[j] <= 0.0) continue;
    acc += w[j];
    last_positive = j;
    if (target < acc) return j;
  }
  return last_positive;  // rounding left target at the very top
}

inline std::size_t argmax(std::span<const double> w) {
  std::size_t best = 0;
  for (std::size_t j = 1; j < w.size(); ++j)
    if (w[j] > w[best]) best = j;
  return best;
}

inline void proportional(std::span<const double> w, std::span<double> p, double mass) {
  const double total = sum(w);
  const auto n = static_cast<double>(w.size());
  for (std::size_t j = 0; j < w.size(); ++j) p[j] = total > 0.0 ? mass * w[j] / total : mass / n;
}

}  // namespace detail

/// The weight tau^alpha eta^beta of an option (eq. 1), given eta^beta; pow is skipped for
/// alpha = 1.
inline double choice_weight(double tau, double alpha, double eta_beta) {
  return (alpha == 1.0 ? tau : std::pow(tau, alpha)) * eta_beta;
}

/// choice_weight of every option: weight[e] = tau[e]^alpha eta_beta[e].
inline void choice_weights(std::span<const double> tau, double alpha,
                           std::span<const double> eta_beta, std::span<double> weight) {
  for (std::size_t e = 0; e < tau.size(); ++e)
    weight[e] = choice_weight(tau[e], alpha, eta_beta[e]);
}

/// Random-proportional rule, eq. (1) of the paper (Ant System) and eq. (11) (AntSLAM).
struct RandomProportional {
  template <class R>
  std::size_t choose(std::span<const double> w, R& rng) const {
    return choose(w, detail::sum(w), rng);
  }
  template <class R>
  std::size_t choose(std::span<const double> w, double total, R& rng) const {
    return detail::roulette(w, total, rng.uniform());
  }
  void distribution(std::span<const double> w, std::span<double> p) const {
    detail::proportional(w, p, 1.0);
  }
};

/// Ant Colony System's pseudo-random-proportional rule (Dorigo & Gambardella 1997): with
/// probability q0 the best option (largest weight), otherwise eq. (1).
struct PseudoRandomProportional {
  double q0 = 0.9;  ///< probability of the greedy choice, in [0, 1]

  template <class R>
  std::size_t choose(std::span<const double> w, R& rng) const {
    if (rng.uniform() < q0) return detail::argmax(w);
    return detail::roulette(w, detail::sum(w), rng.uniform());
  }
  template <class R>
  std::size_t choose(std::span<const double> w, double total, R& rng) const {
    if (rng.uniform() < q0) return detail::argmax(w);
    return detail::roulette(w, total, rng.uniform());
  }
  void distribution(std::span<const double> w, std::span<double> p) const {
    detail::proportional(w, p, 1.0 - q0);
    p[detail::argmax(w)] += q0;
  }
};

/// AntSLAM's rule (Algorithm 2, lines 13-20): with probability p0 a uniform choice among the
/// feasible options, otherwise eq. (11).
struct UniformExploration {
  double p0 = 0.3;  ///< probability of the uniform choice, in [0, 1]

  template <class R>
  std::size_t choose(std::span<const double> w, R& rng) const {
    if (rng.uniform() < p0) return rng.below(static_cast<std::uint32_t>(w.size()));
    return detail::roulette(w, detail::sum(w), rng.uniform());
  }
  template <class R>
  std::size_t choose(std::span<const double> w, double total, R& rng) const {
    if (rng.uniform() < p0) return rng.below(static_cast<std::uint32_t>(w.size()));
    return detail::roulette(w, total, rng.uniform());
  }
  void distribution(std::span<const double> w, std::span<double> p) const {
    detail::proportional(w, p, 1.0 - p0);
    const double uniform = p0 / static_cast<double>(w.size());
    for (double& x : p) x += uniform;
  }
};

}  // namespace antslam::aco
