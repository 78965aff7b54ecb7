// QAPLIB instance reader. Every error names the file, the line and the problem.

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "antslam/qap/qaplib.hpp"
#include "token_reader.hpp"

namespace antslam::qap {

namespace {

/// A whole token as a decimal integer (QAPLIB's are unsigned; a '-' is read, to be refused with
/// its value); empty when it is not one or does not fit.
std::optional<std::int64_t> parse_int64(std::string_view token) {
  std::int64_t value = 0;
  const char* end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, value);
  if (result.ec != std::errc() || result.ptr != end) return std::nullopt;
  return value;
}

std::size_t read_size(detail::TokenReader& r) {
  std::string_view token;
  if (!r.next(token)) r.fail("no size n: the file is empty");
  const auto n = parse_int64(token);
  if (!n) r.fail("size n '" + std::string(token) + "' is not an integer");
  if (*n < 0) r.fail("size n " + std::to_string(*n) + " is negative");
  if (*n == 0) r.fail("size n is 0: a QAP needs at least one facility");
  if (static_cast<std::uint64_t>(*n) > kMaxSize)
    r.fail("size n " + std::to_string(*n) + " is larger than " + std::to_string(kMaxSize));
  return static_cast<std::size_t>(*n);
}

/// Matrix `name`, n x n entries >= 0; `fits(v)` tells whether entry v keeps costs in 64 bits.
template <class Fits>
std::vector<std::int64_t> read_matrix(detail::TokenReader& r, std::size_t n, char name,
                                      Fits&& fits) {
  const std::size_t total = n * n;
  std::vector<std::int64_t> entries;
  std::string_view token;
  while (entries.size() < total) {
    if (!r.next(token))
      r.fail(std::string("matrix ") + name + " has " + std::to_string(entries.size()) + " of " +
             std::to_string(total) + " numbers (the file ends)");
    const std::string entry = std::string("entry (") + std::to_string(entries.size() / n + 1) +
                              ", " + std::to_string(entries.size() % n + 1) + ") of " + name;
    const auto v = parse_int64(token);
    if (!v) r.fail(entry + " '" + std::string(token) + "' is not an integer");
    if (*v < 0) r.fail(entry + " is negative (" + std::to_string(*v) + "): costs must be >= 0");
    if (!fits(*v))
      r.fail(entry + " " + std::to_string(*v) +
             ": costs can exceed 64-bit integers (n^2 max A max B > 2^63 - 1)");
    entries.push_back(*v);
  }
  return entries;
}

}  // namespace

Instance parse_qaplib(std::istream& in, const std::string& source, const std::string& name) {
  detail::TokenReader r(in, source);
  const std::size_t n = read_size(r);
  std::int64_t max_a = 0;
  std::vector<std::int64_t> a = read_matrix(r, n, 'A', [&](std::int64_t v) {
    max_a = std::max(max_a, v);
    return cost_fits(n, max_a, 1);  // with B's entries at most 1
  });
  std::int64_t max_b = 0;
  std::vector<std::int64_t> b = read_matrix(r, n, 'B', [&](std::int64_t v) {
    max_b = std::max(max_b, v);
    return cost_fits(n, max_a, max_b);
  });
  std::string_view extra;
  if (r.next(extra)) r.fail("trailing text '" + std::string(extra) + "' after the two matrices");
  return Instance(n, std::move(a), std::move(b), name);
}

Instance read_qaplib(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot open");
  return parse_qaplib(in, file.string(), file.stem().string());
}

}  // namespace antslam::qap
