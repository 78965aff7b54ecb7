#pragma once
// Maximum (weighted) clique as an aco::SubsetProblem: the ants build maximal cliques (compatible
// = adjacent), as Ant-Clique (Solnon & Fenet 2006) with pheromone on vertices.
//
// The engine minimises a positive cost: here 1 + the weight of the vertices left out of the
// clique, W(V) - W(C) + 1, so the maximum clique has the least cost and a deposit 1 / cost
// stays finite. The heuristic of a vertex is the weight of its closed neighbourhood, an upper
// bound on the weight of any clique that contains it.

#include <cstdint>
#include <span>
#include <vector>

#include "antslam/clique/graph.hpp"

namespace antslam::clique {

class CliqueProblem {
 public:
  explicit CliqueProblem(const Graph& graph);

  std::size_t element_count() const { return graph_->size(); }
  bool compatible(std::uint32_t i, std::uint32_t j) const { return graph_->adjacent(i, j); }
  double heuristic(std::uint32_t v) const { return neighbourhood_weight_[v]; }
  /// W(V) - W(C) + 1 for the clique C (the engine builds cliques only; nothing is checked).
  double cost(std::span<const std::uint32_t> clique) const {
    return graph_->total_weight() - weight_of(*graph_, clique) + 1.0;
  }
  /// The cost of a clique of weight w.
  double cost_of_weight(double w) const { return graph_->total_weight() - w + 1.0; }

  const Graph& graph() const { return *graph_; }

 private:
  const Graph* graph_;
  std::vector<double> neighbourhood_weight_;
};

}  // namespace antslam::clique
