#include <ostream>

#include "antslam/qap/qaplib.hpp"

namespace antslam::qap {

namespace {
void write_matrix(std::ostream& out, std::span<const std::int64_t> m, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) out << (j == 0 ? "" : " ") << m[i * n + j];
    out << '\n';
  }
}
}  // namespace

void write_qaplib(std::ostream& out, const Instance& instance) {
  const std::size_t n = instance.size();
  out << n << "\n\n";
  write_matrix(out, instance.flows(), n);
  out << '\n';
  write_matrix(out, instance.distances(), n);
}

}  // namespace antslam::qap
