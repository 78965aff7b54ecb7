#pragma once
// Array representation of a tour with a position index, as in ACOTSP's local searches:
// succ/pred/between in O(1), and a 2-opt move as the reversal of the shorter of the two paths
// it could reverse (at most n/2 swaps).

#include <cassert>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace antslam::tsp {

class ArrayTour {
 public:
  void assign(std::span<const std::uint32_t> tour) {
    n_ = static_cast<std::uint32_t>(tour.size());
    city_.assign(tour.begin(), tour.end());
    position_.resize(n_);
    for (std::uint32_t p = 0; p < n_; ++p) position_[city_[p]] = p;
  }
  std::span<const std::uint32_t> cities() const { return city_; }
  std::uint32_t size() const { return n_; }
  std::uint32_t position(std::uint32_t c) const { return position_[c]; }

  std::uint32_t succ(std::uint32_t c) const {
    const std::uint32_t p = position_[c] + 1;
    return city_[p == n_ ? 0 : p];
  }
  std::uint32_t pred(std::uint32_t c) const {
    const std::uint32_t p = position_[c];
    return city_[p == 0 ? n_ - 1 : p - 1];
  }
  /// Successor in the given orientation (forward: succ, else pred).
  std::uint32_t next(std::uint32_t c, bool forward) const { return forward ? succ(c) : pred(c); }

  /// True when b lies on the path from a to c in the given orientation (a, c included).
  bool between(std::uint32_t a, std::uint32_t b, std::uint32_t c, bool forward) const {
    if (!forward) std::swap(a, c);
    const std::uint32_t pa = position_[a];
    const std::uint32_t ab = distance_forward(pa, position_[b]);
    return ab <= distance_forward(pa, position_[c]);
  }

  /// Removes edges (p1, p2) and (q1, q2) and adds (p1, q1) and (p2, q2). Requires p2 and q2 to
  /// follow p1 and q1 in the same orientation (both succ or both pred).
  void two_opt_move(std::uint32_t p1, std::uint32_t p2, std::uint32_t q1, std::uint32_t q2) {
    const bool forward = p2 == succ(p1);
    assert(p2 == next(p1, forward) && q2 == next(q1, forward));
    static_cast<void>(q2);
    if (forward) {
      reverse_path(p2, q1);
    } else {
      reverse_path(q1, p2);
    }
  }

  /// Moves city x between the adjacent cities a and b (neither is x): two 2-opt moves.
  void move_city(std::uint32_t x, std::uint32_t a, std::uint32_t b) {
    const bool forward = b == succ(a);  // orientation in which b follows a
    const std::uint32_t p = next(x, !forward);
    const std::uint32_t q = next(x, forward);
    two_opt_move(p, x, a, b);  // p a ... q x b
    two_opt_move(p, a, q, x);  // p q ... a x b
  }

  /// Reverses the forward path from city a to city b (inclusive); the tour is the same cycle
  /// whichever side is reversed, so the shorter side is.
  [[gnu::noinline]] void reverse_path(std::uint32_t a, std::uint32_t b) {
    std::uint32_t i = position_[a];
    std::uint32_t j = position_[b];
    std::uint32_t length = distance_forward(i, j) + 1;
    if (2 * length > n_) {  // reverse the complement: from succ(b) to pred(a)
      const std::uint32_t i2 = j + 1 == n_ ? 0 : j + 1;
      j = i == 0 ? n_ - 1 : i - 1;
      i = i2;
      length = n_ - length;
    }
    for (std::uint32_t s = 0; s < length / 2; ++s) {
      const std::uint32_t ci = city_[i], cj = city_[j];
      city_[i] = cj;
      position_[cj] = i;
      city_[j] = ci;
      position_[ci] = j;
      i = i + 1 == n_ ? 0 : i + 1;
      j = j == 0 ? n_ - 1 : j - 1;
    }
  }

 private:
  std::uint32_t distance_forward(std::uint32_t from, std::uint32_t to) const {
    return to >= from ? to - from : to + n_ - from;
  }

  std::uint32_t n_ = 0;
  std::vector<std::uint32_t> city_;
  std::vector<std::uint32_t> position_;
};

}  // namespace antslam::tsp
