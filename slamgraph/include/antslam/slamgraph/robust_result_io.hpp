#pragma once
// The result file of a robust back end on a pose graph (`antslam-robust-result`, JSON, version
// 1; docs/robust-closures.md): the graph's size, the closures accepted, the times of each stage,
// every setting that ran, precision and recall when the false closures are known, the clique and
// the recalibration of the PCM methods, the kept graph's residuals and the ATE against each
// reference.

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "antslam/slamgraph/ceres_baseline.hpp"
#include "antslam/slamgraph/g2o.hpp"
#include "antslam/slamgraph/robust.hpp"

namespace antslam::slam {

inline constexpr const char* kRobustResultFormat = "antslam-robust-result";
inline constexpr int kRobustResultVersion = 1;

/// The optimised poses against one reference (computed by the caller, e.g. antslam::eval).
struct ReferenceError {
  std::string reference;           ///< the reference's file
  double rmse_m = 0.0;             ///< translation RMSE, metres
  double max_m = 0.0;              ///< largest translation error, metres
  double rotation_rmse_deg = 0.0;  ///< heading RMSE, degrees
};

/// What a robust run was given besides the graph and its settings.
struct RobustRunInputs {
  std::string graph;                       ///< the graph's file
  std::string outliers;                    ///< the false closures' file (used if scores)
  std::optional<AcceptanceScores> scores;  ///< precision and recall, if the false ones are known
  std::vector<ReferenceError> references;  ///< one per reference given
};

/// Writes the result of solve_robust(graph, result.method, settings) as one JSON document
/// (two-space indents, a final newline); `fit` is the kept graph's residual summary.
void write_robust_result(std::ostream& out, const PoseGraph& graph, const RobustSettings& settings,
                         const RobustResult& result, const ResidualSummary& fit,
                         const RobustRunInputs& inputs);

}  // namespace antslam::slam
