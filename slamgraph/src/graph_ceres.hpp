#pragma once
// Ceres on a pose graph's vertex poses (graph_optimize.hpp).

#include "antslam/slamgraph/ceres_baseline.hpp"
#include "antslam/slamgraph/g2o.hpp"

namespace antslam::slam::detail {

/// From the graph's own vertex poses, its fixed vertices (graph_structure.hpp) constant, one
/// residual block per oriented edge (graph_structure.hpp); `robust`: under the loss whose cost is
/// the eq. (10) weight. The result's frames are the vertex poses. Throws std::runtime_error if
/// Ceres fails.
CeresResult optimize_graph_with_ceres(const PoseGraph& graph, bool robust,
                                      const CeresSettings& settings);

}  // namespace antslam::slam::detail
