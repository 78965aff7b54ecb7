#pragma once
// The chi-square distributions of the squared Mahalanobis distance of an SE(2) residual
// (x, y, theta; 3 degrees of freedom) that is as Gaussian as its covariance says, and of one of
// its axes (1 degree of freedom).

namespace antslam::slam {

/// P(X <= x) for X ~ chi-square(3): erf(sqrt(x / 2)) - sqrt(2 x / pi) exp(-x / 2).
double chi_square3_cdf(double x);

/// The x with chi_square3_cdf(x) = probability, for probability in (0, 1) (e.g. 11.345 at 0.99).
/// Throws std::invalid_argument otherwise.
double chi_square3_quantile(double probability);

/// P(X <= x) for X ~ chi-square(1): erf(sqrt(x / 2)).
double chi_square1_cdf(double x);

/// The x with chi_square1_cdf(x) = probability, for probability in (0, 1) (e.g. 6.635 at 0.99).
/// Throws std::invalid_argument otherwise.
double chi_square1_quantile(double probability);

}  // namespace antslam::slam
