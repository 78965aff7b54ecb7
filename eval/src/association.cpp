#include "antslam/eval/association.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <queue>
#include <set>
#include <tuple>

#include "antslam/eval/detail/validation.hpp"

namespace antslam::eval {

namespace {

/// (|dt|, estimate index, reference index): ordered as the greedy association takes them.
using Candidate = std::tuple<double, std::size_t, std::size_t>;

/// Index of the first pose with a stamp >= `stamp` (the size if there is none).
std::size_t first_not_before(const slam::Trajectory& trajectory, double stamp) {
  const auto it =
      std::lower_bound(trajectory.begin(), trajectory.end(), stamp,
                       [](const slam::StampedPose& p, double t) { return p.stamp < t; });
  return static_cast<std::size_t>(it - trajectory.begin());
}

/// The estimate's nearest reference pose among those still free, or none if none is free.
std::optional<Candidate> nearest_free(const slam::Trajectory& reference,
                                      const std::set<std::size_t>& free, double stamp,
                                      std::size_t estimate_index) {
  const auto split = free.lower_bound(first_not_before(reference, stamp));
  std::optional<Candidate> best;
  const auto consider = [&](std::size_t j) {
    const Candidate c{std::abs(reference[j].stamp - stamp), estimate_index, j};
    if (!best || c < *best) best = c;
  };
  if (split != free.begin()) {
    // Among free poses sharing the earlier neighbour's stamp, the first (smallest index).
    const std::size_t earlier = *std::prev(split);
    consider(*free.lower_bound(first_not_before(reference, reference[earlier].stamp)));
  }
  if (split != free.end()) consider(*split);
  return best;
}

}  // namespace

std::optional<std::size_t> find_stamp(const slam::Trajectory& trajectory, double stamp,
                                      double max_dt) {
  const std::size_t later = first_not_before(trajectory, stamp);
  std::optional<std::size_t> best;
  const auto consider = [&](std::size_t j) {
    const double dt = std::abs(trajectory[j].stamp - stamp);
    if (dt <= max_dt && (!best || dt < std::abs(trajectory[*best].stamp - stamp))) best = j;
  };
  // The earlier neighbour first (the first pose with its stamp), so that it wins a tie.
  if (later > 0) consider(first_not_before(trajectory, trajectory[later - 1].stamp));
  if (later < trajectory.size()) consider(later);
  return best;
}

std::vector<PosePair> associate(const slam::Trajectory& estimate, const slam::Trajectory& reference,
                                double max_dt) {
  detail::check_max_dt(max_dt);
  detail::check_sorted(estimate, "estimate");
  detail::check_sorted(reference, "reference");

  // Greedy on the smallest |dt| with lazy updates: the heap holds, for every unmatched estimate,
  // its nearest reference pose at the time it was pushed. If that pose has been taken since, the
  // entry is stale (its |dt| can only have grown) and is pushed again with the new nearest.
  std::set<std::size_t> free;
  for (std::size_t j = 0; j < reference.size(); ++j) free.insert(free.end(), j);
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<>> heap;
  const auto push_nearest = [&](std::size_t i) {
    const auto c = nearest_free(reference, free, estimate[i].stamp, i);
    if (c && std::get<0>(*c) <= max_dt) heap.push(*c);
  };
  for (std::size_t i = 0; i < estimate.size(); ++i) push_nearest(i);

  std::vector<PosePair> pairs;
  while (!heap.empty()) {
    const auto [dt, i, j] = heap.top();
    heap.pop();
    if (free.erase(j) == 0) {
      push_nearest(i);
      continue;
    }
    pairs.push_back({i, j, reference[j].stamp, estimate[i].pose, reference[j].pose});
  }
  std::sort(pairs.begin(), pairs.end(), [](const PosePair& a, const PosePair& b) {
    return a.reference_index < b.reference_index;
  });
  return pairs;
}

}  // namespace antslam::eval
