#include "antslam/qap/instance.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <utility>

namespace antslam::qap {

bool cost_fits(std::size_t n, std::int64_t max_a, std::int64_t max_b) {
  if (max_a == 0 || max_b == 0) return true;
  const auto limit = std::numeric_limits<std::int64_t>::max() / static_cast<std::int64_t>(n * n);
  return max_a <= limit / max_b;  // for integers x, y > 0: x y <= L exactly when x <= L / y
}

Instance::Instance(std::size_t n, std::vector<std::int64_t> flow,
                   std::vector<std::int64_t> distance, std::string name)
    : n_(n), flow_(std::move(flow)), distance_(std::move(distance)), name_(std::move(name)) {
  if (n_ == 0 || n_ > kMaxSize)
    throw std::invalid_argument("qap: n = " + std::to_string(n_) + " is not in 1.." +
                                std::to_string(kMaxSize));
  if (flow_.size() != n_ * n_ || distance_.size() != n_ * n_)
    throw std::invalid_argument("qap: the flow and distance matrices need n^2 entries each");
  const auto [min_a, max_a] = std::minmax_element(flow_.begin(), flow_.end());
  const auto [min_b, max_b] = std::minmax_element(distance_.begin(), distance_.end());
  if (*min_a < 0 || *min_b < 0) throw std::invalid_argument("qap: a matrix entry is negative");
  if (!cost_fits(n_, *max_a, *max_b))
    throw std::invalid_argument("qap: costs can exceed 64-bit integers (n^2 max A max B)");
}

std::int64_t Instance::cost(std::span<const std::uint32_t> p) const {
  std::int64_t total = 0;
  for (std::size_t i = 0; i < n_; ++i) {
    const std::int64_t* a = flow_.data() + i * n_;
    const std::int64_t* b = distance_.data() + std::size_t{p[i]} * n_;
    for (std::size_t j = 0; j < n_; ++j) total += a[j] * b[p[j]];
  }
  return total;
}

}  // namespace antslam::qap
