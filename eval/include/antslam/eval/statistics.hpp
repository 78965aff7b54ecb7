#pragma once
// Summaries of a list of errors. Two conventions, each matching the tool people compare with:
// - ErrorStatistics (ATE, RPE) as the TUM benchmark tools and evo: population standard
//   deviation, sqrt(sum (e - mean)^2 / n).
// - MeanStd (Kuemmerle et al. 2009 relations, and spread over repeated runs as in the laser
//   SLAM evaluation paper, Table I) as Cartographer's compute_relations_metrics: sample standard
//   deviation, sqrt(sum (e - mean)^2 / (n - 1)).

#include <cstddef>
#include <span>

namespace antslam::eval {

/// Statistics of non-negative errors (units of the errors).
struct ErrorStatistics {
  std::size_t count = 0;  ///< number of errors
  double rmse = 0.0;      ///< sqrt(sum e^2 / n)
  double mean = 0.0;      ///< sum e / n
  double median = 0.0;    ///< middle value (mean of the two middle values for even n)
  double std = 0.0;       ///< population standard deviation
  double min = 0.0;       ///< smallest error
  double max = 0.0;       ///< largest error
};

/// Throws std::invalid_argument if `errors` is empty.
ErrorStatistics summarize(std::span<const double> errors);

struct MeanStd {
  std::size_t count = 0;  ///< number of values
  double mean = 0.0;      ///< sum v / n
  double std = 0.0;       ///< sample standard deviation; 0 for a single value
};

/// Throws std::invalid_argument if `values` is empty.
MeanStd mean_std(std::span<const double> values);

}  // namespace antslam::eval
