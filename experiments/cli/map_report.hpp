#pragma once
// The JSON report of `antslam map` (units in the keys): the optimisation (weights of every
// trial, the best map's frames and alignment terms), every loop closure's residual before and
// after, and the evaluation against a reference when one is given.

#include <nlohmann/json.hpp>
#include <optional>

#include "eval/evaluation.hpp"
#include "mapping/optimize_map.hpp"

namespace antslam::cli {

/// A closure is within its Gaussian's 2-sigma ellipse if its Mahalanobis distance is <= 2.
inline constexpr double kClosureSigmas = 2.0;

/// The optimizer's settings and result: weights and chi2 of the scan-matcher map, of every trial
/// and of the best; the best map's frames and, per alignment, its Mahalanobis distance from
/// mu_i and its term of eq. (10).
nlohmann::json optimization_json(const slam::FragmentSet& set,
                                 const mapping::MappingSettings& settings,
                                 const mapping::MappingResult& result);

/// Per closure: hypothesis, residual and Mahalanobis distance before (scan matcher) and after.
nlohmann::json closures_json(const slam::FragmentSet& set, const mapping::MappingResult& result);

/// Scan-matcher and optimized trajectories against the reference (antslam eval's figures).
struct MapEvaluation {
  std::string reference;          ///< file
  eval::Evaluation scan_matcher;  ///< the frontend's trajectory
  eval::Evaluation optimized;     ///< the corrected trajectory
};
nlohmann::json evaluation_json(const MapEvaluation& evaluation);

}  // namespace antslam::cli
