#pragma once
// Random QAP instances and the bundled QAPLIB files for the qap tests.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "antslam/aco/random.hpp"
#include "antslam/qap/instance.hpp"

namespace antslam::qap::testing {

inline std::string data(const std::string& file) {
  return std::string(ANTSLAM_DATA_DIR) + "/qaplib/" + file;
}

/// Entries uniform in [0, 100), B with a zero diagonal; both symmetric when `symmetric`.
inline Instance random_instance(std::size_t n, bool symmetric, std::uint64_t seed) {
  aco::Rng rng(seed);
  const auto matrix = [&](bool zero_diagonal) {
    std::vector<std::int64_t> m(n * n);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) {
        if (symmetric && j < i) {
          m[i * n + j] = m[j * n + i];
        } else {
          m[i * n + j] = i == j && zero_diagonal ? 0 : rng.below(100);
        }
      }
    return m;
  };
  std::vector<std::int64_t> a = matrix(false);
  std::vector<std::int64_t> b = matrix(true);
  return Instance(n, std::move(a), std::move(b), "random");
}

}  // namespace antslam::qap::testing
