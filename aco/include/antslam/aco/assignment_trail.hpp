#pragma once
// Pheromone of an assignment problem: one value tau_il per pair (item i, place l), the desirability
// of putting i at l -- for the QAP, facility i at location l (Stuetzle & Hoos 2000, MMAS-QAP).
// A solution is the vector of places of the items, path[i] = l, a permutation. It is a layered
// trail of n layers (the items) of n options (the places): deposits, the branching factor and
// the converged branching factor 1 are the same; only the mean number of options differs.

#include <cstddef>
#include <stdexcept>
#include <vector>

#include "antslam/aco/layered_trail.hpp"

namespace antslam::aco {

class AssignmentTrail : public LayeredTrail {
 public:
  AssignmentTrail() = default;

  explicit AssignmentTrail(std::size_t n) : LayeredTrail(places(n)) {}

  std::size_t item_count() const { return layer_count(); }

  /// Items placed in a random order choose among the free places: (n + 1) / 2 on average (the
  /// "avg" of Stuetzle & Hoos's tau_min).
  double mean_options() const { return (static_cast<double>(item_count()) + 1.0) / 2.0; }

 private:
  static std::vector<std::size_t> places(std::size_t n) {
    if (n == 0) throw std::invalid_argument("AssignmentTrail: no items");
    return std::vector<std::size_t>(n, n);
  }
};

}  // namespace antslam::aco
