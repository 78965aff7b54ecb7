#pragma once
// The construction fallback of the engine (aco::PermutationFamily): when every candidate of the
// current city is visited, the ant moves to the nearest unvisited city (lowest id on ties). A
// plain scan costs O(n) per fallback, O(n^2) per tour at worst, which dominates construction
// at 20,000 cities. This per-ant structure answers the same query exactly with the spatial
// grid: rings of cells around the city, stopping once no farther cell can hold a nearer city,
// and a scan of the remaining cities once they are fewer than the cells a search would visit.
//
// Removal is lazy: remove() only marks the city, and a query drops the visited cities it meets
// from the lists it reads. A focused ant visits every city but asks for the nearest one a few
// times per tour; keeping the lists exact at every visit cost a fifth of an iteration at 15,000
// cities. Each city leaves a list at most once per tour, so queries stay amortised O(1) per
// city on top of the cells they read, and reset() restores only the cells that changed.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "antslam/tsp/instance.hpp"
#include "antslam/tsp/spatial_grid.hpp"

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
  std::uint32_t nearest(std::uint32_t from);
  std::uint32_t remaining() const { return remaining_; }

 private:
  std::uint32_t scan(std::uint32_t from);

  const Instance* instance_ = nullptr;
  const SpatialGrid* grid_ = nullptr;
  std::vector<std::uint8_t> visited_;
  std::vector<std::uint32_t> listed_;         // the unvisited cities and some visited ones
  std::uint32_t listed_count_ = 0;            // entries of listed_ still in use
  std::vector<std::uint32_t> cell_nodes_;     // grid order; each cell's listed cities first
  std::vector<std::uint32_t> live_;           // listed cities per cell
  std::vector<std::uint32_t> changed_cells_;  // cells whose list a query has shortened
  std::uint32_t remaining_ = 0;
};

}  // namespace antslam::tsp
