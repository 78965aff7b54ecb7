#pragma once
// Word-wise operations on the bit sets of the clique searches (bit v of word v / 64).

#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace antslam::clique::detail {

using Bits = std::vector<std::uint64_t>;

inline std::size_t word_count(std::size_t bits) { return (bits + 63) / 64; }

inline void set_bit(std::span<std::uint64_t> bits, std::uint32_t v) {
  bits[v >> 6U] |= std::uint64_t{1} << (v & 63U);
}

inline bool test_bit(std::span<const std::uint64_t> bits, std::uint32_t v) {
  return ((bits[v >> 6U] >> (v & 63U)) & 1U) != 0;
}

inline void clear_bit(std::span<std::uint64_t> bits, std::uint32_t v) {
  bits[v >> 6U] &= ~(std::uint64_t{1} << (v & 63U));
}

/// Bits 0..count-1 set.
inline Bits all_bits(std::size_t count) {
  Bits bits(word_count(count), ~std::uint64_t{0});
  if (count % 64 != 0) bits.back() = (std::uint64_t{1} << (count % 64)) - 1;
  if (count == 0) bits.clear();
  return bits;
}

inline bool any(std::span<const std::uint64_t> bits) {
  for (const std::uint64_t w : bits)
    if (w != 0) return true;
  return false;
}

inline std::size_t count(std::span<const std::uint64_t> bits) {
  std::size_t total = 0;
  for (const std::uint64_t w : bits) total += static_cast<std::size_t>(std::popcount(w));
  return total;
}

/// |a AND b|.
inline std::size_t count_and(std::span<const std::uint64_t> a, std::span<const std::uint64_t> b) {
  std::size_t total = 0;
  for (std::size_t k = 0; k < a.size(); ++k)
    total += static_cast<std::size_t>(std::popcount(a[k] & b[k]));
  return total;
}

/// Calls f(v) for every set bit v, increasing.
template <class F>
void for_each_bit(std::span<const std::uint64_t> bits, F&& f) {
  for (std::size_t k = 0; k < bits.size(); ++k)
    for (std::uint64_t w = bits[k]; w != 0; w &= w - 1)
      f(static_cast<std::uint32_t>(k * 64 + static_cast<std::size_t>(std::countr_zero(w))));
}

}  // namespace antslam::clique::detail
