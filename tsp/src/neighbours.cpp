#include "antslam/tsp/neighbours.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace antslam::tsp {

namespace {

using Candidate = std::pair<double, std::uint32_t>;  // (distance, node): lexicographic order

/// Keeps the k smallest candidates seen, sorted.
class BestK {
 public:
  explicit BestK(std::size_t k) : k_(k) { best_.reserve(k + 1); }
  void clear() { best_.clear(); }
  bool full() const { return best_.size() == k_; }
  double worst() const { return best_.back().first; }
  void offer(Candidate c) {
    if (full() && !(c < best_.back())) return;
    best_.insert(std::upper_bound(best_.begin(), best_.end(), c), c);
    if (best_.size() > k_) best_.pop_back();
  }
  void write(std::uint32_t* out) const {
    for (const Candidate& c : best_) *out++ = c.second;
  }

 private:
  std::size_t k_;
  std::vector<Candidate> best_;
};

void check_k(const Instance& instance, std::size_t k) {
  if (k == 0 || k >= instance.size())
    throw std::invalid_argument("neighbour lists: k = " + std::to_string(k) + " is not in 1.." +
                                std::to_string(instance.size() - 1));
}

}  // namespace

std::vector<std::uint32_t> nearest_neighbours_brute_force(const Instance& instance, std::size_t k) {
  check_k(instance, k);
  const auto n = static_cast<std::uint32_t>(instance.size());
  std::vector<std::uint32_t> lists(std::size_t{n} * k);
  BestK best(k);
  for (std::uint32_t i = 0; i < n; ++i) {
    best.clear();
    for (std::uint32_t j = 0; j < n; ++j)
      if (j != i) best.offer({instance.distance(i, j), j});
    best.write(lists.data() + std::size_t{i} * k);
  }
  return lists;
}

std::vector<std::uint32_t> nearest_neighbours(const Instance& instance, std::size_t k,
                                              const SpatialGrid* grid) {
  const EdgeWeightType type = instance.type();
  if (grid == nullptr || type == EdgeWeightType::geo || type == EdgeWeightType::explicit_matrix ||
      k + 1 >= instance.size())
    return nearest_neighbours_brute_force(instance, k);
  check_k(instance, k);
  const auto n = static_cast<std::uint32_t>(instance.size());
  const double margin = 1e-9 * grid->cell_size();  // guards the cell assignment's rounding
  std::vector<std::uint32_t> lists(std::size_t{n} * k);
  BestK best(k);
  for (std::uint32_t i = 0; i < n; ++i) {
    best.clear();
    const int column = grid->column_of(i), row = grid->row_of(i);
    for (int r = 0;; ++r) {
      grid->for_each_cell_in_ring(column, row, r, [&](std::size_t cell) {
        for (std::uint32_t j : grid->points_in(cell))
          if (j != i) best.offer({instance.distance(i, j), j});
      });
      if (grid->ring_covers_grid(column, row, r)) break;
      const double reach = std::max(0.0, static_cast<double>(r) * grid->cell_size() - margin);
      if (best.full() && instance.distance_lower_bound(reach) > best.worst()) break;
    }
    best.write(lists.data() + std::size_t{i} * k);
  }
  return lists;
}

}  // namespace antslam::tsp
