#include "tsp/nearest_unvisited.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

namespace antslam::tsp {

namespace {
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
}

NearestUnvisited::NearestUnvisited(const Instance* instance, const SpatialGrid* grid)
    : instance_(instance), grid_(grid) {
  const std::size_t n = instance_->size();
  unvisited_.resize(n);
  slot_.resize(n);
  if (grid_ != nullptr) {
    cell_nodes_.resize(n);
    cell_slot_.resize(n);
    live_.resize(grid_->cell_count());
  }
  reset();
}

void NearestUnvisited::reset() {
  std::iota(unvisited_.begin(), unvisited_.end(), 0U);
  std::iota(slot_.begin(), slot_.end(), 0U);
  remaining_ = static_cast<std::uint32_t>(unvisited_.size());
  if (grid_ == nullptr) return;
  const auto nodes = grid_->nodes();
  std::copy(nodes.begin(), nodes.end(), cell_nodes_.begin());
  for (std::uint32_t s = 0; s < nodes.size(); ++s) cell_slot_[nodes[s]] = s;
  for (std::size_t c = 0; c < live_.size(); ++c) live_[c] = grid_->start(c + 1) - grid_->start(c);
}

void NearestUnvisited::remove(std::uint32_t node) {
  const std::uint32_t last = unvisited_[--remaining_];
  unvisited_[slot_[node]] = last;
  slot_[last] = slot_[node];
  if (grid_ == nullptr) return;
  const std::size_t cell = grid_->cell_index(grid_->column_of(node), grid_->row_of(node));
  const std::uint32_t end = grid_->start(cell) + --live_[cell];
  const std::uint32_t moved = cell_nodes_[end];
  std::swap(cell_nodes_[cell_slot_[node]], cell_nodes_[end]);
  cell_slot_[moved] = cell_slot_[node];
  cell_slot_[node] = end;
}

std::uint32_t NearestUnvisited::scan(std::uint32_t from) const {
  std::uint32_t best = kNone;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::uint32_t r = 0; r < remaining_; ++r) {
    const std::uint32_t j = unvisited_[r];
    const double d = instance_->distance(from, j);
    if (d < best_d || (d == best_d && j < best)) {
      best_d = d;
      best = j;
    }
  }
  return best;
}

std::uint32_t NearestUnvisited::nearest(std::uint32_t from) const {
  if (grid_ == nullptr) return scan(from);
  const int column = grid_->column_of(from), row = grid_->row_of(from);
  const double margin = 1e-9 * grid_->cell_size();
  std::uint32_t best = kNone;
  double best_d = std::numeric_limits<double>::infinity();
  for (int r = 0;; ++r) {
    const auto side = static_cast<std::uint64_t>(2 * r + 1);
    if (side * side > remaining_) return scan(from);  // fewer cities left than cells to visit
    grid_->for_each_cell_in_ring(column, row, r, [&](std::size_t cell) {
      const std::uint32_t begin = grid_->start(cell);
      for (std::uint32_t s = begin; s < begin + live_[cell]; ++s) {
        const std::uint32_t j = cell_nodes_[s];
        const double d = instance_->distance(from, j);
        if (d < best_d || (d == best_d && j < best)) {
          best_d = d;
          best = j;
        }
      }
    });
    if (grid_->ring_covers_grid(column, row, r)) return best;
    const double reach = std::max(0.0, static_cast<double>(r) * grid_->cell_size() - margin);
    if (best != kNone && instance_->distance_lower_bound(reach) > best_d) return best;
  }
}

}  // namespace antslam::tsp
