#pragma once
// A QAP instance (Koopmans & Beckmann 1957, QAPLIB's convention): n facilities go to n
// locations; A holds the flows between facilities, B the distances between locations, and the
// assignment p (facility i at location p[i]) costs sum_ij a_ij b_p(i)p(j). Entries are integers
// >= 0, and n^2 max(A) max(B) fits in 64 bits, which bounds every cost and every pair-swap delta
// (local_search.hpp), so that they are exact in std::int64_t.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace antslam::qap {

/// Largest n the reader and Instance accept (two n x n matrices of 8-byte entries: 64 MiB).
inline constexpr std::size_t kMaxSize = 2048;

/// Whether n^2 max_a max_b <= 2^63 - 1 (max_a, max_b >= 0, n <= kMaxSize).
bool cost_fits(std::size_t n, std::int64_t max_a, std::int64_t max_b);

class Instance {
 public:
  /// An empty instance (n = 0), to be assigned.
  Instance() = default;

  /// flow and distance: n x n, row-major. Throws std::invalid_argument unless 1 <= n <= kMaxSize,
  /// both have n^2 entries >= 0 and cost_fits holds.
  Instance(std::size_t n, std::vector<std::int64_t> flow, std::vector<std::int64_t> distance,
           std::string name = {});

  std::size_t size() const { return n_; }
  const std::string& name() const { return name_; }
  std::int64_t flow(std::size_t i, std::size_t j) const { return flow_[i * n_ + j]; }
  std::int64_t distance(std::size_t k, std::size_t l) const { return distance_[k * n_ + l]; }
  std::span<const std::int64_t> flows() const { return flow_; }
  std::span<const std::int64_t> distances() const { return distance_; }

  /// sum_ij a_ij b_p(i)p(j) of the permutation p (p[i]: the location of facility i).
  std::int64_t cost(std::span<const std::uint32_t> p) const;

 private:
  std::size_t n_ = 0;
  std::vector<std::int64_t> flow_;
  std::vector<std::int64_t> distance_;
  std::string name_;
};

}  // namespace antslam::qap
