#pragma once
// The TSP as an engine problem (satisfies aco::PermutationProblem): TSPLIB distances, the
// ants' candidate lists, and the local search's neighbour lists with cached distances.
//
// Memory: a full distance matrix (4 n^2 bytes) only up to ProblemSettings::matrix_limit
// cities; above it distances are computed from coordinates on the fly (a square root each).
// Neighbour lists and their distances cost 12 n k bytes; the engine's pheromone lives only on
// candidate edges (16 n k bytes). A 20,000-city instance with k = 20 needs about 11 MB here.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "antslam/tsp/instance.hpp"
#include "antslam/tsp/nearest_unvisited.hpp"
#include "antslam/tsp/spatial_grid.hpp"

namespace antslam::tsp {

struct ProblemSettings {
  std::size_t candidates = 20;      ///< nearest neighbours an ant chooses among (ACOTSP nn_ants)
  std::size_t ls_neighbours = 20;   ///< nearest neighbours local search tries (as ACOTSP)
  std::size_t matrix_limit = 2000;  ///< cities up to which the full distance matrix is stored
};

class TspProblem {
 public:
  /// Throws std::invalid_argument if a list length is 0 (lists are capped at n - 1).
  explicit TspProblem(Instance instance, const ProblemSettings& settings = {});

  std::size_t size() const { return n_; }

  double distance(std::uint32_t i, std::uint32_t j) const {
    if (!matrix_.empty()) return matrix_[std::size_t{i} * n_ + j];
    return instance_->distance(i, j);
  }

  /// The ants' candidate list of node i, nearest first.
  std::span<const std::uint32_t> candidates(std::uint32_t i) const {
    return {neighbours_.data() + std::size_t{i} * width_, candidates_};
  }
  /// The local search's neighbour list of node i, nearest first, and the distances to them.
  std::span<const std::uint32_t> neighbours(std::uint32_t i) const {
    return {neighbours_.data() + std::size_t{i} * width_, ls_neighbours_};
  }
  std::span<const double> neighbour_distances(std::uint32_t i) const {
    return {neighbour_distance_.data() + std::size_t{i} * width_, ls_neighbours_};
  }

  /// Length of a closed tour.
  double cost(std::span<const std::uint32_t> tour) const;

  /// Exact fast nearest-unvisited search for the construction fallback, one per ant
  /// (aco::PermutationProblemWithNearestSearch).
  NearestUnvisited make_nearest_search() const {
    return NearestUnvisited(instance_.get(), grid_.get());
  }

  const Instance& instance() const { return *instance_; }
  bool has_matrix() const { return !matrix_.empty(); }
  /// Bytes held by this object (matrix, lists, grid), for the scaling notes.
  std::size_t memory_bytes() const;

 private:
  std::shared_ptr<const Instance> instance_;  // shared: searches outlive moves of the problem
  std::shared_ptr<const SpatialGrid> grid_;
  std::size_t n_ = 0;
  std::size_t candidates_ = 0;
  std::size_t ls_neighbours_ = 0;
  std::size_t width_ = 0;  // stored list length: max(candidates_, ls_neighbours_)
  std::vector<std::uint32_t> neighbours_;
  std::vector<double> neighbour_distance_;
  std::vector<std::int32_t> matrix_;
};

}  // namespace antslam::tsp
