#include "antslam/eval/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace antslam::eval {

namespace {

double mean_of(std::span<const double> values) {
  return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

double sum_of_squared_deviations(std::span<const double> values, double mean) {
  double sum = 0.0;
  for (double v : values) sum += (v - mean) * (v - mean);
  return sum;
}

}  // namespace

ErrorStatistics summarize(std::span<const double> errors) {
  if (errors.empty()) throw std::invalid_argument("summarize: no errors to summarize");
  const double n = static_cast<double>(errors.size());
  ErrorStatistics s;
  s.count = errors.size();
  s.mean = mean_of(errors);
  double sum_squares = 0.0;
  for (double e : errors) sum_squares += e * e;
  s.rmse = std::sqrt(sum_squares / n);
  s.std = std::sqrt(sum_of_squared_deviations(errors, s.mean) / n);
  std::vector<double> sorted(errors.begin(), errors.end());
  std::sort(sorted.begin(), sorted.end());
  const std::size_t half = sorted.size() / 2;
  s.median = sorted.size() % 2 == 1 ? sorted[half] : 0.5 * (sorted[half - 1] + sorted[half]);
  s.min = sorted.front();
  s.max = sorted.back();
  return s;
}

MeanStd mean_std(std::span<const double> values) {
  if (values.empty()) throw std::invalid_argument("mean_std: no values");
  MeanStd s;
  s.count = values.size();
  s.mean = mean_of(values);
  if (values.size() > 1)
    s.std = std::sqrt(sum_of_squared_deviations(values, s.mean) /
                      static_cast<double>(values.size() - 1));
  return s;
}

}  // namespace antslam::eval
