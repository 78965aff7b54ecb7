#pragma once
// Pheromone of a symmetric permutation problem, stored only on candidate edges: for every node
// i, one value per entry of its nearest-neighbour list. Memory is O(n k) instead of O(n^2), so
// 20,000-city instances fit easily. An edge (i, j) that appears in both i's and j's lists has
// two copies that every operation keeps equal. Edges outside every candidate list carry no
// pheromone: deposits on them are dropped (they are chosen only by the nearest-unvisited
// fallback of the construction).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>
#include <vector>

#include "antslam/aco/pheromone_values.hpp"

namespace antslam::aco {

class EdgeTrail : public PheromoneValues {
 public:
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

  EdgeTrail() = default;

  /// neighbours: n rows of k candidate ids, row-major.
  EdgeTrail(std::size_t n, std::size_t k, std::vector<std::uint32_t> neighbours)
      : PheromoneValues(n * k),
        n_(n),
        k_(k),
        neighbour_(std::move(neighbours)),
        mirror_(n * k, kNone) {
    if (neighbour_.size() != n * k) throw std::invalid_argument("EdgeTrail: size mismatch");
    for (std::size_t i = 0; i < n_; ++i)
      for (std::size_t r = 0; r < k_; ++r) {
        const std::uint32_t j = neighbour_[i * k_ + r];
        if (j >= n_ || j == i) throw std::invalid_argument("EdgeTrail: bad candidate entry");
        mirror_[i * k_ + r] = find_in_row(j, static_cast<std::uint32_t>(i));
      }
  }

  std::size_t node_count() const { return n_; }
  std::size_t candidate_count() const { return k_; }
  std::span<const std::uint32_t> neighbours(std::uint32_t i) const {
    return {neighbour_.data() + std::size_t{i} * k_, k_};
  }
  std::span<const double> row(std::uint32_t i) const {
    return {tau_.data() + std::size_t{i} * k_, k_};
  }
  double entry(std::size_t index) const { return tau_[index]; }

  /// Index of edge (i, j) in i's row, else in j's row, else kNone.
  std::uint32_t edge_index(std::uint32_t i, std::uint32_t j) const {
    const std::uint32_t e = find_in_row(i, j);
    return e != kNone ? e : find_in_row(j, i);
  }
  /// Pheromone on edge (i, j); 0 when it is not a candidate edge.
  double edge(std::uint32_t i, std::uint32_t j) const {
    const std::uint32_t e = edge_index(i, j);
    return e == kNone ? 0.0 : tau_[e];
  }

  /// Applies f(tau) to edge (i, j) if it is a candidate edge; returns its index (or kNone).
  template <class F>
  std::uint32_t update_edge(std::uint32_t i, std::uint32_t j, F&& f) {
    const std::uint32_t e = edge_index(i, j);
    if (e == kNone) return kNone;
    f(tau_[e]);
    if (mirror_[e] != kNone) tau_[mirror_[e]] = tau_[e];
    return e;
  }
  /// Index of the other copy of entry e, or kNone.
  std::uint32_t mirror(std::uint32_t e) const { return mirror_[e]; }

  // --- operations shared with the layered trail, used by the pheromone-update policies ---

  std::size_t decision_count() const { return n_; }
  /// Mean number of options per decision, as ACOTSP: (k + 1) / 2 on candidate lists.
  double mean_options() const { return (static_cast<double>(k_) + 1.0) / 2.0; }
  /// A converged node of a symmetric tour keeps two strong edges.
  static constexpr double converged_branching() { return 2.0; }

  /// Calls f(tau) once on every candidate edge of the closed tour. The tour visits every node
  /// once, so its edges are distinct and chunks of it touch disjoint entries.
  template <class F>
  void update_path(std::span<const std::uint32_t> tour, F&& f, const ChunkedFor& parallel = {}) {
    const auto edges = [&](std::size_t begin, std::size_t end) {
      for (std::size_t s = begin; s < end; ++s)
        update_edge(tour[s], tour[s + 1 == tour.size() ? 0 : s + 1], f);
    };
    parallel(tour.size(), edges, ChunkedFor::kMinSearchChunk);
  }

  void deposit(std::span<const std::uint32_t> tour, double amount,
               const ChunkedFor& parallel = {}) {
    const auto add = [amount](double& t) { t += amount; };
    update_path(tour, add, parallel);
  }

  /// Mean lambda-branching factor over the candidate lists (as ACOTSP's node_branching).
  double branching_factor(double lambda) const {
    double total = 0.0;
    for (std::uint32_t i = 0; i < n_; ++i) {
      total += branches(row(i), lambda);
    }
    return total / static_cast<double>(n_);
  }

 private:
  std::uint32_t find_in_row(std::uint32_t i, std::uint32_t j) const {
    const std::uint32_t* row = neighbour_.data() + std::size_t{i} * k_;
    for (std::size_t r = 0; r < k_; ++r)
      if (row[r] == j) return static_cast<std::uint32_t>(std::size_t{i} * k_ + r);
    return kNone;
  }

  std::size_t n_ = 0;
  std::size_t k_ = 0;
  std::vector<std::uint32_t> neighbour_;
  std::vector<std::uint32_t> mirror_;
};

}  // namespace antslam::aco
