#pragma once
// Array representation of a tour with a position index, as in ACOTSP's local searches:
// succ/pred/between in O(1), and a 2-opt move as the reversal of the shorter of the two paths
// it could reverse (at most n/2 swaps; TwoLevelTour does it in O(sqrt n)). The length of every tour
// edge is kept beside it, so that the local search reads tour-edge lengths from a small hot array
// instead of the distance matrix (or a square root).

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "antslam/tsp/problem.hpp"

namespace antslam::tsp {

class ArrayTour {
 public:
  void assign(std::span<const std::uint32_t> tour, const TspProblem& problem) {
    problem_ = &problem;
    n_ = static_cast<std::uint32_t>(tour.size());
    city_.assign(tour.begin(), tour.end());
    position_.resize(n_);
    for (std::uint32_t p = 0; p < n_; ++p) position_[city_[p]] = p;
    length_.resize(n_);
    for (std::uint32_t p = 0; p < n_; ++p) length_[p] = edge_at(p);
  }
  std::span<const std::uint32_t> cities() const { return city_; }
  void copy_to(std::vector<std::uint32_t>& out) const { out.assign(city_.begin(), city_.end()); }
  std::uint32_t size() const { return n_; }
  std::uint32_t position(std::uint32_t c) const { return position_[c]; }

  std::uint32_t succ(std::uint32_t c) const { return city_[after(position_[c])]; }
  std::uint32_t pred(std::uint32_t c) const { return city_[before(position_[c])]; }
  /// Successor in the given orientation (forward: succ, else pred).
  std::uint32_t next(std::uint32_t c, bool forward) const { return forward ? succ(c) : pred(c); }
  /// Length of the edge from c to next(c, forward).
  double next_length(std::uint32_t c, bool forward) const {
    const std::uint32_t p = position_[c];
    return length_[forward ? p : before(p)];
  }

  /// True when b lies on the path from a to c in the given orientation (a, c included).
  bool between(std::uint32_t a, std::uint32_t b, std::uint32_t c, bool forward) const {
    if (!forward) std::swap(a, c);
    const std::uint32_t pa = position_[a];
    return distance_forward(pa, position_[b]) <= distance_forward(pa, position_[c]);
  }

  /// Reverses the forward path from city a to city b (inclusive); the tour is the same cycle
  /// whichever side is reversed, so the shorter side is.
  void reverse_path(std::uint32_t a, std::uint32_t b) {
    std::uint32_t i = position_[a];
    std::uint32_t j = position_[b];
    std::uint32_t length = distance_forward(i, j) + 1;
    if (2 * length > n_) {  // reverse the complement: from succ(b) to pred(a)
      const std::uint32_t first = after(j);
      j = before(i);
      i = first;
      length = n_ - length;
    }
    const std::uint32_t first = i, last = j;
    // The segment's inner edges reverse their order: edge i + m swaps with edge j - 1 - m.
    const std::uint32_t swaps = length > 1 ? (length - 1) / 2 : 0;
    for (std::uint32_t m = 0, e = i, f = before(j); m < swaps; ++m) {
      std::swap(length_[e], length_[f]);
      e = after(e);
      f = before(f);
    }
    for (std::uint32_t s = 0; s < length / 2; ++s) {
      const std::uint32_t ci = city_[i], cj = city_[j];
      city_[i] = cj;
      position_[cj] = i;
      city_[j] = ci;
      position_[ci] = j;
      i = after(i);
      j = before(j);
    }
    length_[before(first)] = edge_at(before(first));  // the two edges that changed
    length_[last] = edge_at(last);
  }

 private:
  std::uint32_t after(std::uint32_t p) const { return p + 1 == n_ ? 0 : p + 1; }
  std::uint32_t before(std::uint32_t p) const { return p == 0 ? n_ - 1 : p - 1; }
  std::uint32_t distance_forward(std::uint32_t from, std::uint32_t to) const {
    return to >= from ? to - from : to + n_ - from;
  }
  double edge_at(std::uint32_t p) const { return problem_->distance(city_[p], city_[after(p)]); }

  const TspProblem* problem_ = nullptr;
  std::uint32_t n_ = 0;
  std::vector<std::uint32_t> city_;
  std::vector<std::uint32_t> position_;
  std::vector<double> length_;  // length_[p]: edge from position p to p + 1
};

}  // namespace antslam::tsp
