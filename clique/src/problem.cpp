#include "antslam/clique/problem.hpp"

namespace antslam::clique {

CliqueProblem::CliqueProblem(const Graph& graph)
    : graph_(&graph), neighbourhood_weight_(graph.size()) {
  for (std::uint32_t v = 0; v < graph.size(); ++v)
    neighbourhood_weight_[v] = graph.weight(v) + weight_of(graph, graph.neighbours(v));
}

}  // namespace antslam::clique
