#pragma once
// The JSON report of the pipeline (units in the keys): the log and the frontend's settings and
// result, the optimisation (weights of every trial, the best map's frames and alignment terms),
// every loop closure's residual before and after, the evaluation against a reference when one
// was given, and the times.

#include <nlohmann/json.hpp>
#include <string>

#include "antslam/mapping/pipeline.hpp"

namespace antslam::mapping {

/// A closure is within its Gaussian's 2-sigma ellipse if its Mahalanobis distance is <= 2.
inline constexpr double kClosureSigmas = 2.0;

/// The optimizer's settings and result: weights and chi2 of the scan-matcher map, of every trial,
/// of the best and of the map (after closing the loops: the closures it distrusted); the map's
/// frames and, per alignment, its Mahalanobis distance from mu_i and its term of eq. (10).
nlohmann::json optimization_json(const slam::FragmentSet& set, const MappingSettings& settings,
                                 const MappingResult& result);

/// Per closure: hypothesis, residual and Mahalanobis distance before (scan matcher) and after,
/// and whether the closing trusted it.
nlohmann::json closures_json(const slam::FragmentSet& set, const MappingResult& result);

/// Both trajectories' errors against the reference (antslam eval's figures).
nlohmann::json evaluation_json(const MapEvaluation& evaluation);

/// The verdict: closures outside 2 sigma (by fragment pair), fallbacks, largest residuals, line.
nlohmann::json verdict_json(const slam::FragmentSet& set, const Verdict& verdict);

/// The whole report of a pipeline run on the log at `log_path`.
nlohmann::json report_json(const std::string& log_path, const PipelineSettings& settings,
                           const PipelineResult& result);

}  // namespace antslam::mapping
