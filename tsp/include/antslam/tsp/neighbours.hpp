#pragma once
// Nearest-neighbour lists: for every node its k nearest other nodes by TSPLIB distance,
// nearest first, ties broken by the lower node id. Coordinate instances use the spatial grid
// (about O(n k) overall); GEO and EXPLICIT instances use brute force (O(n^2 log k); they are
// small in practice).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "antslam/tsp/instance.hpp"
#include "antslam/tsp/spatial_grid.hpp"

namespace antslam::tsp {

/// Row-major n x k matrix of neighbour ids. k must be in [1, n - 1]. `grid` (over
/// instance.coords()) may be null; it is used only for EUC_2D, CEIL_2D and ATT.
std::vector<std::uint32_t> nearest_neighbours(const Instance& instance, std::size_t k,
                                              const SpatialGrid* grid);

/// The same lists by comparing every pair; the reference the grid search is tested against.
std::vector<std::uint32_t> nearest_neighbours_brute_force(const Instance& instance, std::size_t k);

}  // namespace antslam::tsp
