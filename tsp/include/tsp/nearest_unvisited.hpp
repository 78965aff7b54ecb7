#pragma once
// The construction fallback of the engine (aco::PermutationFamily): when every candidate of the
// current city is visited, the ant moves to the nearest unvisited city (lowest id on ties). A
// plain scan costs O(n) per fallback, O(n^2) per tour at worst, which dominates construction
// at 20,000 cities. This per-ant structure answers the same query exactly with the spatial
// grid: rings of cells around the city, stopping once no farther cell can hold a nearer city,
// and a scan of the remaining cities once they are fewer than the cells a search would visit.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "tsp/instance.hpp"
#include "tsp/spatial_grid.hpp"

namespace antslam::tsp {

class NearestUnvisited {
 public:
  NearestUnvisited() = default;
  /// grid may be null (GEO, EXPLICIT): then every query scans the unvisited cities.
  NearestUnvisited(const Instance* instance, const SpatialGrid* grid);

  /// Marks every city unvisited.
  void reset();
  /// Marks `node` visited (it must be unvisited).
  void remove(std::uint32_t node);
  /// The unvisited city nearest to `from` (TSPLIB distance, then lowest id). At least one city
  /// must be unvisited.
  std::uint32_t nearest(std::uint32_t from) const;
  std::uint32_t remaining() const { return remaining_; }

 private:
  std::uint32_t scan(std::uint32_t from) const;

  const Instance* instance_ = nullptr;
  const SpatialGrid* grid_ = nullptr;
  std::vector<std::uint32_t> unvisited_;   // compact list of the unvisited cities
  std::vector<std::uint32_t> slot_;        // position of each city in unvisited_
  std::vector<std::uint32_t> cell_nodes_;  // grid order; each cell's unvisited cities first
  std::vector<std::uint32_t> cell_slot_;   // position of each city in cell_nodes_
  std::vector<std::uint32_t> live_;        // unvisited cities per cell
  std::uint32_t remaining_ = 0;
};

}  // namespace antslam::tsp
