#pragma once
// Two-level tour (Fredman, Johnson, McGeoch & Ostheimer 1995, "Data structures for traveling
// salesmen"): the tour is a sequence of segments of about sqrt(n) cities, each with a reversal
// bit. A 2-opt move, the reversal of a path, costs O(sqrt n) instead of the array's O(n): the
// segments holding the path's ends are split there, and the run of whole segments between them
// is reversed by reversing their order and flipping their bits (the shorter side of the cycle,
// as with the array); a path inside one segment is reversed in place. succ, pred and between
// stay O(1).
//
// Both levels are arrays here: every segment is a range of one array of cities, so a split
// moves no city, and the segment order is an array of segment ids indexed by rank. Segments
// only split; when there are twice as many as after the last cut, the tour is cut again into
// equal segments (O(n), amortised O(sqrt n) per move). The interface is ArrayTour's, so the
// local search runs on either.

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "antslam/tsp/problem.hpp"

namespace antslam::tsp {

class TwoLevelTour {
 public:
  void assign(std::span<const std::uint32_t> tour, const TspProblem& problem);
  std::uint32_t size() const { return n_; }
  /// The tour in its current orientation, from the first city of the first segment.
  void copy_to(std::vector<std::uint32_t>& out) const;
  std::size_t segment_count() const { return segments_.size(); }

  std::uint32_t succ(std::uint32_t c) const {
    const Segment& s = segments_[segment_of_[c]];
    const std::uint32_t p = index_[c];
    if (!s.reversed) return p + 1 < s.end ? city_[p + 1] : first(next_segment(s));
    return p > s.begin ? city_[p - 1] : first(next_segment(s));
  }
  std::uint32_t pred(std::uint32_t c) const {
    const Segment& s = segments_[segment_of_[c]];
    const std::uint32_t p = index_[c];
    if (!s.reversed) return p > s.begin ? city_[p - 1] : last(previous_segment(s));
    return p + 1 < s.end ? city_[p + 1] : last(previous_segment(s));
  }
  std::uint32_t next(std::uint32_t c, bool forward) const { return forward ? succ(c) : pred(c); }
  double next_length(std::uint32_t c, bool forward) const {
    return problem_->distance(c, next(c, forward));
  }

  /// True when b lies on the path from a to c in the given orientation (a, c included).
  bool between(std::uint32_t a, std::uint32_t b, std::uint32_t c, bool forward) const {
    if (!forward) std::swap(a, c);
    const std::uint64_t ka = key(a), kb = key(b), kc = key(c);
    return ka <= kc ? ka <= kb && kb <= kc : kb >= ka || kb <= kc;
  }

  /// Reverses the forward path from city a to city b (inclusive), or its complement: the same
  /// cycle.
  void reverse_path(std::uint32_t a, std::uint32_t b);

 private:
  struct Segment {
    std::uint32_t begin = 0, end = 0;  // cities city_[begin, end)
    std::uint32_t rank = 0;            // place in the tour: order_[rank] is this segment
    bool reversed = false;             // tour order runs from end - 1 down to begin
  };

  std::uint32_t first(const Segment& s) const {
    return s.reversed ? city_[s.end - 1] : city_[s.begin];
  }
  std::uint32_t last(const Segment& s) const {
    return s.reversed ? city_[s.begin] : city_[s.end - 1];
  }
  const Segment& next_segment(const Segment& s) const {
    return segments_[order_[s.rank + 1 == order_.size() ? 0 : s.rank + 1]];
  }
  const Segment& previous_segment(const Segment& s) const {
    return segments_[order_[s.rank == 0 ? order_.size() - 1 : s.rank - 1]];
  }
  /// Place of c along the tour: its segment's rank, then its place inside the segment.
  std::uint64_t key(std::uint32_t c) const {
    const Segment& s = segments_[segment_of_[c]];
    const std::uint32_t inside = s.reversed ? s.end - 1 - index_[c] : index_[c] - s.begin;
    return (static_cast<std::uint64_t>(s.rank) << 32) | inside;
  }

  /// Cuts the tour (in `order`) into segments of about sqrt(n) cities.
  void cut(std::span<const std::uint32_t> order);
  /// Splits c's segment so that c is the first city of its segment in tour order.
  void split_before(std::uint32_t c);
  /// Reverses the path a..b that lies inside one segment, a before b.
  void reverse_inside(std::uint32_t a, std::uint32_t b);
  /// Reverses the run of `count` whole segments starting at rank `from` (cyclically).
  void reverse_run(std::uint32_t from, std::uint32_t count);

  const TspProblem* problem_ = nullptr;
  std::uint32_t n_ = 0;
  std::vector<std::uint32_t> city_;        // segments' cities, each segment a range
  std::vector<std::uint32_t> index_;       // city -> its place in city_
  std::vector<std::uint32_t> segment_of_;  // city -> segment id
  std::vector<Segment> segments_;          // by id
  std::vector<std::uint32_t> order_;       // rank -> segment id
  std::vector<std::uint32_t> scratch_;     // the tour while it is cut again
  std::size_t cut_segments_ = 0;           // segments right after the last cut
};

}  // namespace antslam::tsp
