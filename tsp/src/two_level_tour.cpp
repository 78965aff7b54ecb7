#include "antslam/tsp/two_level_tour.hpp"

#include <algorithm>
#include <cmath>

namespace antslam::tsp {

void TwoLevelTour::assign(std::span<const std::uint32_t> tour, const TspProblem& problem) {
  problem_ = &problem;
  n_ = static_cast<std::uint32_t>(tour.size());
  index_.resize(n_);
  segment_of_.resize(n_);
  cut(tour);
}

void TwoLevelTour::copy_to(std::vector<std::uint32_t>& out) const {
  out.clear();
  out.reserve(n_);
  for (const std::uint32_t id : order_) {
    const Segment& s = segments_[id];
    if (!s.reversed) {
      out.insert(out.end(), city_.begin() + s.begin, city_.begin() + s.end);
    } else {
      for (std::uint32_t p = s.end; p-- > s.begin;) out.push_back(city_[p]);
    }
  }
}

void TwoLevelTour::cut(std::span<const std::uint32_t> order) {
  city_.assign(order.begin(), order.end());
  const auto size = std::max<std::uint32_t>(
      1, static_cast<std::uint32_t>(std::lround(std::sqrt(static_cast<double>(n_)))));
  segments_.clear();
  order_.clear();
  for (std::uint32_t begin = 0; begin < n_; begin += size) {
    const auto id = static_cast<std::uint32_t>(segments_.size());
    const std::uint32_t end = std::min(n_, begin + size);
    segments_.push_back({begin, end, id, false});
    order_.push_back(id);
    for (std::uint32_t p = begin; p < end; ++p) {
      index_[city_[p]] = p;
      segment_of_[city_[p]] = id;
    }
  }
  cut_segments_ = segments_.size();
}

void TwoLevelTour::split_before(std::uint32_t c) {
  const std::uint32_t id = segment_of_[c];
  const Segment s = segments_[id];
  if (first(s) == c) return;
  const std::uint32_t p = index_[c];
  // The cities before c and from c on, in tour order, as ranges of city_.
  std::pair<std::uint32_t, std::uint32_t> before{s.begin, p}, from{p, s.end};
  if (s.reversed) {
    before = {p + 1, s.end};
    from = {s.begin, p + 1};
  }
  // The smaller part becomes a new segment, in front of s when it is the part before c.
  const bool new_in_front = before.second - before.first <= from.second - from.first;
  const auto moved = new_in_front ? before : from;
  const auto kept = new_in_front ? from : before;
  const std::uint32_t rank = new_in_front ? s.rank : s.rank + 1;
  const auto new_id = static_cast<std::uint32_t>(segments_.size());
  segments_[id].begin = kept.first;
  segments_[id].end = kept.second;
  segments_.push_back({moved.first, moved.second, rank, s.reversed});
  for (std::uint32_t q = moved.first; q < moved.second; ++q) segment_of_[city_[q]] = new_id;
  order_.insert(order_.begin() + rank, new_id);
  for (std::uint32_t r = rank; r < order_.size(); ++r) segments_[order_[r]].rank = r;
}

void TwoLevelTour::reverse_inside(std::uint32_t a, std::uint32_t b) {
  std::uint32_t lo = index_[a], hi = index_[b];
  if (segments_[segment_of_[a]].reversed) std::swap(lo, hi);
  for (; lo < hi; ++lo, --hi) {
    std::swap(city_[lo], city_[hi]);
    index_[city_[lo]] = lo;
    index_[city_[hi]] = hi;
  }
}

void TwoLevelTour::reverse_run(std::uint32_t from, std::uint32_t count) {
  const auto segments = static_cast<std::uint32_t>(order_.size());
  const auto step = [segments](std::uint32_t r) { return r + 1 == segments ? 0 : r + 1; };
  const auto back = [segments](std::uint32_t r) { return r == 0 ? segments - 1 : r - 1; };
  std::uint32_t i = from, j = (from + count - 1) % segments;
  for (std::uint32_t m = 0; m < count / 2; ++m, i = step(i), j = back(j))
    std::swap(order_[i], order_[j]);
  for (std::uint32_t m = 0, r = from; m < count; ++m, r = step(r)) {
    Segment& s = segments_[order_[r]];
    s.reversed = !s.reversed;
    s.rank = r;
  }
}

void TwoLevelTour::reverse_path(std::uint32_t a, std::uint32_t b) {
  if (a == b || succ(b) == a) return;  // one city, or the whole cycle: the same cycle
  if (segment_of_[a] == segment_of_[b]) {
    if (key(a) <= key(b)) {
      reverse_inside(a, b);
    } else {  // the path runs around the tour; its complement lies inside the segment
      reverse_inside(succ(b), pred(a));
    }
    return;
  }
  split_before(a);
  split_before(succ(b));  // b becomes the last city of its segment
  const auto segments = static_cast<std::uint32_t>(order_.size());
  const std::uint32_t ra = segments_[segment_of_[a]].rank;
  const std::uint32_t rb = segments_[segment_of_[b]].rank;
  const std::uint32_t count = (rb + segments - ra) % segments + 1;
  if (2 * count > segments) {
    reverse_run((rb + 1) % segments, segments - count);
  } else {
    reverse_run(ra, count);
  }
  if (segments_.size() > 2 * cut_segments_) {
    copy_to(scratch_);
    cut(scratch_);
  }
}

}  // namespace antslam::tsp
