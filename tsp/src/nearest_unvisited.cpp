#include "antslam/tsp/nearest_unvisited.hpp"

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
  visited_.resize(n);
  listed_.resize(n);
  std::iota(listed_.begin(), listed_.end(), 0U);
  listed_count_ = static_cast<std::uint32_t>(n);
  if (grid_ != nullptr) {
    const auto nodes = grid_->nodes();
    cell_nodes_.assign(nodes.begin(), nodes.end());
    live_.resize(grid_->cell_count());
    for (std::size_t c = 0; c < live_.size(); ++c) live_[c] = grid_->start(c + 1) - grid_->start(c);
  }
  reset();
}

void NearestUnvisited::reset() {
  std::fill(visited_.begin(), visited_.end(), 0);
  remaining_ = static_cast<std::uint32_t>(visited_.size());
  if (listed_count_ != listed_.size()) {
    std::iota(listed_.begin(), listed_.end(), 0U);
    listed_count_ = static_cast<std::uint32_t>(listed_.size());
  }
  if (grid_ == nullptr) return;
  const auto nodes = grid_->nodes();
  for (const std::size_t cell : changed_cells_) {
    const std::uint32_t begin = grid_->start(cell), end = grid_->start(cell + 1);
    std::copy(nodes.begin() + begin, nodes.begin() + end, cell_nodes_.begin() + begin);
    live_[cell] = end - begin;
  }
  changed_cells_.clear();
}

void NearestUnvisited::remove(std::uint32_t node) {
  visited_[node] = 1;
  --remaining_;
}

std::uint32_t NearestUnvisited::scan(std::uint32_t from) {
  std::uint32_t best = kNone;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::uint32_t r = 0; r < listed_count_;) {
    const std::uint32_t j = listed_[r];
    if (visited_[j] != 0) {
      listed_[r] = listed_[--listed_count_];
      continue;
    }
    const double d = instance_->distance(from, j);
    if (d < best_d || (d == best_d && j < best)) {
      best_d = d;
      best = j;
    }
    ++r;
  }
  return best;
}

std::uint32_t NearestUnvisited::nearest(std::uint32_t from) {
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
      std::uint32_t* nodes = cell_nodes_.data() + begin;
      const std::uint32_t listed = live_[cell];
      std::uint32_t live = listed;
      for (std::uint32_t s = 0; s < live;) {
        const std::uint32_t j = nodes[s];
        if (visited_[j] != 0) {
          nodes[s] = nodes[--live];  // drop the visited city; reset() restores the cell
          continue;
        }
        const double d = instance_->distance(from, j);
        if (d < best_d || (d == best_d && j < best)) {
          best_d = d;
          best = j;
        }
        ++s;
      }
      if (live == listed) return;
      if (listed == grid_->start(cell + 1) - begin)
        changed_cells_.push_back(static_cast<std::uint32_t>(cell));
      live_[cell] = live;
    });
    if (grid_->ring_covers_grid(column, row, r)) return best;
    const double reach = std::max(0.0, static_cast<double>(r) * grid_->cell_size() - margin);
    if (best != kNone && instance_->distance_lower_bound(reach) > best_d) return best;
  }
}

}  // namespace antslam::tsp
