#include "antslam/slamgraph/chi_square.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace antslam::slam {

double chi_square3_cdf(double x) {
  if (!(x > 0.0)) return 0.0;
  return std::erf(std::sqrt(0.5 * x)) - std::sqrt(2.0 * x / std::numbers::pi) * std::exp(-0.5 * x);
}

double chi_square1_cdf(double x) {
  if (!(x > 0.0)) return 0.0;
  return std::erf(std::sqrt(0.5 * x));
}

namespace {

/// The x with cdf(x) = probability by bisection (cdf increasing from 0 at 0 to 1).
double quantile(double (*cdf)(double), double probability) {
  if (!(probability > 0.0 && probability < 1.0))
    throw std::invalid_argument("chi-square quantile: probability must be in (0, 1)");
  double lo = 0.0, hi = 1.0;
  while (cdf(hi) < probability) hi *= 2.0;
  for (int i = 0; i < 200 && hi - lo > 1e-12 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (cdf(mid) < probability ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

double chi_square3_quantile(double probability) { return quantile(chi_square3_cdf, probability); }

double chi_square1_quantile(double probability) { return quantile(chi_square1_cdf, probability); }

}  // namespace antslam::slam
